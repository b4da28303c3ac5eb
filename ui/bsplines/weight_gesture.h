#pragma once
/// \file weight_gesture.h
/// A point's weight (NURBS, c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ) changed on the canvas, on top of the
/// point editor's gestures (docs/classroom.md): Shift+wheel over a point (over the selected
/// point when none is under the mouse) and the + and − keys on the selected point multiply its
/// weight by 2^(±1/4) a notch, the result snapped to two significant digits and held as the
/// exact decimal it is (6/5, 21/25), so that the weights field and the exact panel stay
/// readable. A weight stays within [kMinWeight, kMaxWeight]: w ≤ 0 cannot be reached. The
/// tab makes each change an undo step (consecutive changes of one point merge into one, as the
/// arrow keys' nudges do).

#include "core/exact/rational.h"

#include <QObject>

namespace granota::ui {

class PointEditor;

/// The smallest and the largest weight the gesture reaches (each a notch's end, not a refusal).
inline const Rational kMinWeight = frac(1, 1000);
inline const Rational kMaxWeight = Rational(1000);
/// Notches that double a weight.
constexpr int kWeightNotchesPerDoubling = 4;

/// w × 2^(steps / kWeightNotchesPerDoubling), rounded to two significant digits, exactly, and
/// kept in [kMinWeight, kMaxWeight]. Differs from w for steps ≠ 0 unless w is at that end.
Rational steppedWeight(const Rational& w, int steps);

class WeightGesture : public QObject {
    Q_OBJECT
public:
    /// Watches `editor`'s canvas (installed after the editor's own filter, so it sees the
    /// events first; it takes only Shift+wheel and + and − without Ctrl).
    explicit WeightGesture(PointEditor* editor, QObject* parent = nullptr);

signals:
    /// Point `index`'s weight is to change by `steps` notches (± some).
    void weightStepped(int index, int steps);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    PointEditor* m_editor;
    int m_wheelRemainder = 0; ///< eighths of a degree short of a notch (touchpads send small deltas)
};

} // namespace granota::ui
