#pragma once
/// \file focus_frame.h
/// Where the keyboard is, seen from the back of a classroom (docs/classroom.md, "Keyboard"):
/// every control with the keyboard focus has a thick ring round it in one strong colour
/// (FocusRing), and a canvas, which fills its space, draws the same ring just inside itself
/// (drawFocusFrame). The styles' own hints (a pale tint, a 1 px outline) vanish on a projector.
/// Exports never draw either.

#include <QColor>
#include <QPointer>
#include <QRect>
#include <QVector>
#include <QWidget>

class QPainter;
class QPalette;
class QRectF;

namespace granota::ui {

/// The ring's colour: a dark blue, 8:1 against the window's light grey and 4:1 against the
/// selection's blue, so it reads on a washed-out projector.
inline const QColor kFocusRingColour(0x00, 0x40, 0xa0);
/// The ring's width in pixels at the normal scale (× presentationScale in presentation mode).
inline constexpr double kFocusRingWidth = 3.0;

/// The ring, kFocusRingWidth × `scale` wide, just inside `rect` (a canvas's own). `palette`
/// is unused (the ring has one colour everywhere) and kept for the callers' sake.
void drawFocusFrame(QPainter& painter, const QRectF& rect, const QPalette& palette, double scale);

/// Marks `widget` as drawing its own ring (drawFocusFrame): FocusRing leaves it alone.
void setDrawsOwnFocusFrame(QWidget* widget);
/// Whether `widget` draws its own ring: a canvas (the main window's status bar then shows the
/// canvas's keys while it has the focus).
bool drawsOwnFocusFrame(const QWidget* widget);

/// The ring round the control that has the keyboard focus in `window`: a widget of its own
/// over the whole window, transparent to the mouse, that follows the focus and the moves of
/// the control and of what holds it (a panel that scrolls), cut to what of it is in view.
class FocusRing : public QWidget {
    Q_OBJECT
public:
    explicit FocusRing(QWidget* window);
    /// 1, or presentationScale(true) in presentation mode: the ring grows with the lines.
    void setScale(double scale);
    /// The control the ring is round now (null when none, or when it draws its own).
    QWidget* target() const { return m_target; }
    /// The ring's width in pixels now.
    int ringWidth() const;
    /// The whole ring in the window's coordinates: the control's rectangle grown by ringWidth()
    /// (the widget itself is that, less what lies outside the window).
    QRect ringRect() const { return m_ring; }

protected:
    void paintEvent(QPaintEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void follow(QWidget* focus);
    void place();
    void watch(bool on);

    QPointer<QWidget> m_window;
    QPointer<QWidget> m_target;
    QVector<QPointer<QWidget>> m_watched; ///< the target and what holds it, up to the window
    QRect m_ring;                         ///< the whole ring, in the window's coordinates
    QRect m_clip;                         ///< in the widget's coordinates: what of the ring may be drawn
    double m_scale = 1.0;
};

} // namespace granota::ui
