#pragma once
/// \file language.h
/// Catalan and English, switchable live (docs/classroom.md): installs Granota's translation and Qt's
/// own (qtbase_ca.qm, for the standard dialogs), remembers the choice in QSettings, and
/// picks Catalan on a Catalan system when nothing was chosen. Widgets retranslate on the
/// QEvent::LanguageChange that installing a translator sends.

#include <QString>
#include <QStringList>

namespace granota::ui {

/// "ca" and "en".
QStringList availableLanguages();
/// The remembered language, else Catalan on a Catalan system, else English.
QString preferredLanguage();
/// Switches the whole application to `language` and remembers it. False for an unknown code.
bool setLanguage(const QString& language, bool remember = true);
/// The language in use.
QString currentLanguage();

} // namespace granota::ui
