#include "ui/bsplines/weight_gesture.h"

#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"

#include <QKeyEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {
constexpr int kWheelNotch = 120; ///< angleDelta of one wheel notch (eighths of a degree)
} // namespace

Rational steppedWeight(const Rational& w, int steps)
{
    if (steps == 0)
        return w;
    const double target = toDouble(w) * std::exp2(static_cast<double>(steps) / kWeightNotchesPerDoubling);
    if (!(target > toDouble(kMinWeight)))
        return kMinWeight;
    if (!(target < toDouble(kMaxWeight)))
        return kMaxWeight;
    // Two significant digits: mantissa 10..99 (or 100) times 10^e, the power of ten exactly.
    const int e = static_cast<int>(std::floor(std::log10(target))) - 1;
    const long mantissa = std::lround(target / std::pow(10.0, e));
    Rational ten(1);
    for (int i = 0; i < std::abs(e); ++i)
        ten *= Rational(10);
    const Rational out = e >= 0 ? Rational(Rational(mantissa) * ten) : Rational(Rational(mantissa) / ten);
    return std::clamp(out, kMinWeight, kMaxWeight);
}

WeightGesture::WeightGesture(PointEditor* editor, QObject* parent) : QObject(parent), m_editor(editor)
{
    editor->canvas()->installEventFilter(this);
}

bool WeightGesture::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_editor->canvas())
        return QObject::eventFilter(watched, event);
    if (event->type() == QEvent::Wheel) {
        auto* e = static_cast<QWheelEvent*>(event);
        if (!(e->modifiers() & Qt::ShiftModifier) || !m_editor->handlesVisible())
            return false; // the canvas zooms (and hidden points have no weight to turn, as for + and −)
        int index = m_editor->pick(e->position());
        if (index < 0)
            index = m_editor->selected();
        if (index < 0)
            return false;
        // Some platforms turn Shift+wheel into a horizontal wheel.
        const int delta = e->angleDelta().y() != 0 ? e->angleDelta().y() : e->angleDelta().x();
        m_wheelRemainder += delta;
        const int steps = m_wheelRemainder / kWheelNotch;
        m_wheelRemainder -= steps * kWheelNotch;
        if (steps != 0) {
            m_editor->setSelected(index);
            emit weightStepped(index, steps);
        }
        return true;
    }
    if (event->type() == QEvent::KeyPress) {
        auto* e = static_cast<QKeyEvent*>(event);
        if (e->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
            return false; // Ctrl++ zooms
        const int index = m_editor->selected();
        if (index < 0 || !m_editor->handlesVisible())
            return false;
        switch (e->key()) {
        case Qt::Key_Plus:
        case Qt::Key_Equal: emit weightStepped(index, 1); return true; // + without Shift on many keyboards
        case Qt::Key_Minus: emit weightStepped(index, -1); return true;
        default: return false;
        }
    }
    return false;
}

} // namespace granota::ui
