#pragma once
/// \file blank_screen.h
/// View ▸ Blank the screen (B, a presenter remote's blank key): black over the whole window,
/// menus and status bar included, so that the room looks at the teacher; B again, or a click,
/// brings the window back as it was (docs/classroom.md, "Presenter remote").
#include <QWidget>

namespace granota::ui {

class BlankScreen : public QWidget {
    Q_OBJECT
public:
    /// Hidden over `window` until setBlank(true).
    explicit BlankScreen(QWidget* window);
    void setBlank(bool on);
    bool blank() const { return isVisible(); }

signals:
    /// The user brought the window back with a click.
    void dismissed();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
};

} // namespace granota::ui
