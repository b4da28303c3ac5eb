#pragma once
/// \file decasteljau_parameter_control.h
/// The parameter t ∈ [0, 1] of a Bézier curve as a slider with a spin box beside it. The
/// spin box shows three decimals and also accepts fractions ("1/3"): the exact value typed
/// is kept, so t = 1/3 gives the exact tables of Def 2.4 at 1/3, not at 0.333.
/// Used by the De Casteljau tab and, sharing one t, by the Bernstein tab.

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace granota::ui {

class ParameterSpinBox;

class DeCasteljauParameterControl : public QWidget {
    Q_OBJECT
public:
    explicit DeCasteljauParameterControl(QWidget* parent = nullptr);

    double value() const { return m_value; }
    /// Sets t (clamped to [0, 1]) without emitting valueChanged.
    void setValue(double t);
    void retranslate();

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* spinBox() const;

    /// The undo merge id of the current gesture: the moves of one slider drag (or one run of
    /// arrow keys, or one spin box held down) share it and make one undo step; releasing the
    /// slider or finishing a typed value starts a new gesture with a new id.
    int gestureMergeId() const;

signals:
    /// The user moved the slider or typed a value.
    void valueChanged(double t);

private:
    void fromSlider(int position);
    void fromSpinBox(double value);

    QLabel* m_label;
    QSlider* m_slider;
    ParameterSpinBox* m_spin;
    double m_value = 0.5;
    int m_gesture = 0;
};

} // namespace granota::ui
