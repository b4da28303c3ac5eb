#include "ui/decasteljau/decasteljau_parameter_control.h"

#include "core/exact/rational.h"
#include "ui/common/decimal_spin_box.h"
#include "ui/common/number_text.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>
#include <optional>

namespace granota::ui {

namespace {
constexpr int kSliderSteps = 1000;   ///< slider resolution: t in steps of 0.001
constexpr int kDecimals = 3;         ///< digits the spin box shows
constexpr double kHalfStep = 0.0005; ///< a typed fraction is kept when it rounds to the shown value
} // namespace

/// A spin box that also reads fractions and remembers the exact value typed.
class ParameterSpinBox : public DecimalSpinBox {
public:
    using DecimalSpinBox::DecimalSpinBox;

    /// The value last typed, when it was a valid number in [0, 1].
    std::optional<double> typed() const { return m_typed; }
    void forgetTyped() { m_typed.reset(); }

    QValidator::State validate(QString& text, int& pos) const override
    {
        const QString s = text.trimmed();
        if (s.isEmpty() || s.endsWith(QLatin1Char('/')) || s == QLatin1String("-") || s.endsWith(QLatin1Char('.')) ||
            s.endsWith(QLatin1Char(',')))
            return QValidator::Intermediate;
        if (s.contains(QLatin1Char('/'))) {
            const auto q = parseRational(s.toStdString());
            if (!q)
                return QValidator::Intermediate;
            return (*q >= 0 && *q <= 1) ? QValidator::Acceptable : QValidator::Intermediate;
        }
        return DecimalSpinBox::validate(text, pos);
    }
    double valueFromText(const QString& text) const override
    {
        const QString s = text.trimmed();
        if (const auto q = parseTypedRational(s)) {
            const double v = toDouble(*q);
            if (std::isfinite(v) && v >= 0 && v <= 1) {
                m_typed = v;
                return v;
            }
        }
        return DecimalSpinBox::valueFromText(text);
    }
    void stepBy(int steps) override
    {
        m_typed.reset();
        DecimalSpinBox::stepBy(steps);
    }

private:
    mutable std::optional<double> m_typed;
};

DeCasteljauParameterControl::DeCasteljauParameterControl(QWidget* parent)
    : QWidget(parent), m_label(new QLabel(this)), m_slider(new QSlider(Qt::Horizontal, this)), m_spin(new ParameterSpinBox(this))
{
    m_slider->setRange(0, kSliderSteps);
    m_slider->setMinimumWidth(120);
    m_spin->setRange(0.0, 1.0);
    m_spin->setDecimals(kDecimals);
    m_spin->setSingleStep(0.01);
    m_spin->setKeyboardTracking(false);
    m_spin->setAccelerated(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spin);
    connect(m_slider, &QSlider::valueChanged, this, &DeCasteljauParameterControl::fromSlider);
    connect(m_spin, &QDoubleSpinBox::valueChanged, this, &DeCasteljauParameterControl::fromSpinBox);
    connect(m_slider, &QSlider::sliderReleased, this, [this] { ++m_gesture; });
    connect(m_spin, &QDoubleSpinBox::editingFinished, this, [this] { ++m_gesture; });
    setValue(m_value);
    retranslate();
}

QDoubleSpinBox* DeCasteljauParameterControl::spinBox() const { return m_spin; }

int DeCasteljauParameterControl::gestureMergeId() const
{
    constexpr int kBase = 0x74000000; // "t": far from the tabs' other merge ids
    return kBase + (m_gesture & 0xffff);
}

void DeCasteljauParameterControl::retranslate()
{
    m_label->setText(QStringLiteral("t ="));
    const QString tip = tr("The parameter t ∈ [0, 1] of the curve c(t) (Def 2.4). Type a decimal or a fraction such as 1/3.");
    m_label->setToolTip(tip);
    m_slider->setToolTip(tip);
    m_spin->setToolTip(tip);
    m_slider->setAccessibleName(tr("Parameter t"));
    m_spin->setAccessibleName(tr("Parameter t"));
}

void DeCasteljauParameterControl::setValue(double t)
{
    if (!std::isfinite(t))
        return;
    m_value = std::clamp(t, 0.0, 1.0);
    const QSignalBlocker blockSlider(m_slider), blockSpin(m_spin);
    m_slider->setValue(static_cast<int>(std::lround(m_value * kSliderSteps)));
    m_spin->setValue(m_value);
    m_spin->forgetTyped();
}

void DeCasteljauParameterControl::fromSlider(int position)
{
    m_value = static_cast<double>(position) / kSliderSteps;
    {
        const QSignalBlocker block(m_spin);
        m_spin->setValue(m_value);
        m_spin->forgetTyped();
    }
    emit valueChanged(m_value);
}

void DeCasteljauParameterControl::fromSpinBox(double value)
{
    // A fraction typed by hand wins over its three-decimal rounding.
    const auto typed = m_spin->typed();
    m_value = (typed && std::fabs(*typed - value) <= kHalfStep) ? *typed : value;
    {
        const QSignalBlocker block(m_slider);
        m_slider->setValue(static_cast<int>(std::lround(m_value * kSliderSteps)));
    }
    emit valueChanged(m_value);
}

} // namespace granota::ui
