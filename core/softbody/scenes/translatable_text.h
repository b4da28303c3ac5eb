#pragma once
/// \file translatable_text.h
/// The core is Qt-free, yet some of its tables hold the English texts the GUI shows (the scene
/// parameters' labels and tooltips, the scenes' titles). They are marked with Qt's own
/// `QT_TRANSLATE_NOOP(context, text)`, which lupdate finds (it reads the core too,
/// ui/CMakeLists.txt) and which is just `text` here; the GUI passes the text, with the same
/// context, to QCoreApplication::translate. The context is the widget class that shows the
/// text, so translations/granota_*.ts keep one <context> per widget.

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(context, text) text
#endif
