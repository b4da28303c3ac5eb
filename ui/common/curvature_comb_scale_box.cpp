#include "ui/common/curvature_comb_scale_box.h"

#include <QSignalBlocker>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {
constexpr int kShownDigits = 4; ///< significant digits shown (the comb's key shows the scale too)
constexpr int kDecimals = 9;    ///< what the value keeps: scales of small curves are small

/// `v` rounded to two significant digits: the first step from "automatic".
double roundTwoDigits(double v)
{
    if (!(v > 0) || !std::isfinite(v))
        return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(v)) - 1);
    return std::round(v / power) * power;
}
} // namespace

CurvatureCombScaleBox::CurvatureCombScaleBox(QWidget* parent) : DecimalSpinBox(parent)
{
    setDecimals(kDecimals);
    setRange(0.0, kMaxScale);
    setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    setKeyboardTracking(false);
    setAccelerated(true);
    setValue(0.0);
    retranslate();
}

void CurvatureCombScaleBox::setScale(double scale)
{
    const QSignalBlocker block(this);
    setValue(std::isfinite(scale) && scale > 0 ? scale : 0.0);
}

void CurvatureCombScaleBox::retranslate()
{
    setSpecialValueText(tr("automatic"));
    setToolTip(tr("The comb's scale: a tooth is |κ| × this long (in the curve's units). Automatic: the 90th "
                  "percentile of |κ| gives teeth 15 % of the control polygon's size, and the teeth rescale as "
                  "the curve changes; a number keeps them comparable. 0 is automatic."));
    setAccessibleName(tr("Comb scale"));
}

void CurvatureCombScaleBox::stepBy(int steps)
{
    if (value() == 0.0 && steps != 0) {
        setValue(roundTwoDigits(m_automatic)); // from automatic, start at the comb as it is
        return;
    }
    DecimalSpinBox::stepBy(steps);
}

QString CurvatureCombScaleBox::textFromValue(double value) const
{
    // kShownDigits significant digits, in fixed notation (what the box reads back), without
    // trailing zeros, in the box's locale as QDoubleSpinBox writes it.
    const int magnitude = value > 0 ? static_cast<int>(std::floor(std::log10(value))) : 0;
    const int decimals = std::clamp(kShownDigits - 1 - magnitude, 0, kDecimals);
    QString text = locale().toString(value, 'f', decimals);
    text.remove(locale().groupSeparator());
    const QString point = locale().decimalPoint();
    if (text.contains(point)) {
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(point))
            text.chop(point.size());
    }
    return text;
}

} // namespace granota::ui
