#include "ui/shell/blank_screen.h"

#include "ui/common/focus_frame.h"

#include <QEvent>
#include <QPalette>

namespace granota::ui {

BlankScreen::BlankScreen(QWidget* window) : QWidget(window)
{
    setObjectName(QStringLiteral("blankScreen"));
    setAutoFillBackground(true);
    QPalette black = palette();
    black.setColor(QPalette::Window, Qt::black);
    setPalette(black);
    setFocusPolicy(Qt::NoFocus);
    setDrawsOwnFocusFrame(this); // nothing to ring on a black screen
    hide();
    window->installEventFilter(this);
}

void BlankScreen::setBlank(bool on)
{
    if (on == isVisible())
        return;
    if (on) {
        setGeometry(parentWidget()->rect());
        show();
        raise();
    } else {
        hide();
    }
}

bool BlankScreen::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == parentWidget() && event->type() == QEvent::Resize)
        setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void BlankScreen::mousePressEvent(QMouseEvent*)
{
    setBlank(false);
    emit dismissed();
}

} // namespace granota::ui
