#pragma once
/// \file curvature_comb_scale_box.h
/// The user's scale of a curvature comb (curvature_comb.h), beside the comb's toggle on the
/// De Casteljau and Fitting tabs: the model length of a tooth per unit of |κ|, or
/// "automatic" (the value 0, the default), where the comb chooses it from the curve. A fixed
/// scale keeps the teeth comparable while the curve is edited; the automatic one rescales.
/// Up and Down from "automatic" start at the automatic scale of the comb shown, rounded.

#include "ui/common/decimal_spin_box.h"

namespace granota::ui {

class CurvatureCombScaleBox : public DecimalSpinBox {
    Q_OBJECT
public:
    explicit CurvatureCombScaleBox(QWidget* parent = nullptr);

    static constexpr double kMaxScale = 1e9;

    /// The scale chosen; 0 is automatic.
    double scale() const { return value(); }
    /// Shows `scale` without valueChanged (documents, undo).
    void setScale(double scale);
    /// The scale the automatic comb uses now: where the first step from "automatic" goes.
    void setAutomaticScale(double scale) { m_automatic = scale; }
    /// The special text ("automatic") and the tooltip.
    void retranslate();

    void stepBy(int steps) override;
    QString textFromValue(double value) const override;

private:
    double m_automatic = 1.0;
};

} // namespace granota::ui
