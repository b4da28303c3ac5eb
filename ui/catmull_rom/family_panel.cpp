#include "ui/catmull_rom/family_panel.h"

#include "ui/common/number_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

#include <cmath>

namespace granota::ui {

namespace {

constexpr int kFamilySteps = CatmullRomSettings::kTcbSteps;

/// A slider over [−1, 1] in steps of 1/kFamilySteps.
QSlider* familyUnitSlider(QWidget* parent)
{
    auto* s = new QSlider(Qt::Horizontal, parent);
    s->setRange(-kFamilySteps, kFamilySteps);
    s->setPageStep(kFamilySteps / 4);
    return s;
}

int familySliderValue(const Rational& r) { return static_cast<int>(std::lround(toDouble(r) * kFamilySteps)); }

} // namespace

FamilyPanel::FamilyPanel(QWidget* parent) : QGroupBox(parent)
{
    m_familyLabel = new QLabel(this);
    m_familyCombo = new QComboBox(this);
    for (CurveFamily f : kCurveFamilies)
        m_familyCombo->addItem(QString(), curveFamilyKey(f));
    m_familyLabel->setBuddy(m_familyCombo);
    m_ruleLabel = new QLabel(this);
    m_ruleLabel->setWordWrap(true);
    m_cardinalLabel = new QLabel(this);
    m_cardinalSlider = familyUnitSlider(this);
    m_cardinalLabel->setBuddy(m_cardinalSlider);
    m_knotLabel = new QLabel(this);
    m_knotLabel->setWordWrap(true);
    m_allKnots = new QCheckBox(this);
    for (std::size_t k = 0; k < 3; ++k) {
        m_tcbLabels[k] = new QLabel(this);
        m_tcbSliders[k] = familyUnitSlider(this);
        m_tcbLabels[k]->setBuddy(m_tcbSliders[k]);
    }
    m_resetTangents = new QPushButton(this);

    auto* layout = new QGridLayout(this);
    layout->addWidget(m_familyLabel, 0, 0);
    layout->addWidget(m_familyCombo, 0, 1);
    layout->addWidget(m_ruleLabel, 1, 0, 1, 2);
    layout->addWidget(m_cardinalLabel, 2, 0);
    layout->addWidget(m_cardinalSlider, 2, 1);
    layout->addWidget(m_knotLabel, 3, 0, 1, 2);
    layout->addWidget(m_allKnots, 4, 0, 1, 2);
    for (int k = 0; k < 3; ++k) {
        layout->addWidget(m_tcbLabels[static_cast<std::size_t>(k)], 5 + k, 0);
        layout->addWidget(m_tcbSliders[static_cast<std::size_t>(k)], 5 + k, 1);
    }
    layout->addWidget(m_resetTangents, 8, 0, 1, 2);
    layout->setColumnStretch(1, 1);

    connect(m_familyCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!m_showing && i >= 0 && i < static_cast<int>(kCurveFamilies.size()))
            emit familyChosen(kCurveFamilies[static_cast<std::size_t>(i)]);
    });
    connect(m_cardinalSlider, &QSlider::valueChanged, this, [this](int v) {
        if (!m_showing)
            emit cardinalTensionChosen(frac(v, kFamilySteps));
    });
    for (int k = 0; k < 3; ++k)
        connect(m_tcbSliders[static_cast<std::size_t>(k)], &QSlider::valueChanged, this, [this, k](int v) {
            if (!m_showing)
                emit tcbChosen(k, frac(v, kFamilySteps));
        });
    connect(m_allKnots, &QCheckBox::toggled, this, [this] {
        showSettings(m_shown, m_selectedPoint); // the label names what the sliders now move
    });
    connect(m_resetTangents, &QPushButton::clicked, this, &FamilyPanel::resetTangentsAsked);
}

bool FamilyPanel::allKnots() const { return m_allKnots->isChecked() || m_selectedPoint < 0; }

void FamilyPanel::showSettings(const CatmullRomSettings& settings, int selectedPoint)
{
    m_showing = true;
    m_shown = settings;
    m_selectedPoint = selectedPoint;
    for (std::size_t i = 0; i < kCurveFamilies.size(); ++i)
        if (kCurveFamilies[i] == settings.family)
            m_familyCombo->setCurrentIndex(static_cast<int>(i));
    const bool cardinal = settings.family == CurveFamily::Cardinal;
    const bool kb = settings.family == CurveFamily::KochanekBartels;
    const bool hermite = settings.family == CurveFamily::Hermite;
    m_cardinalLabel->setVisible(cardinal);
    m_cardinalSlider->setVisible(cardinal);
    m_cardinalSlider->setValue(familySliderValue(settings.cardinalTension));
    const Rational tau = (Rational(1) - settings.cardinalTension) / Rational(2);
    m_cardinalLabel->setText(
        tr("c = %1 (τ = %2):").arg(displayText(toString(settings.cardinalTension)), displayText(toString(tau))));
    for (QWidget* w : {static_cast<QWidget*>(m_knotLabel), static_cast<QWidget*>(m_allKnots)})
        w->setVisible(kb);
    const TcbKnot<Rational> k = selectedPoint >= 0 ? tcbAt(settings, static_cast<std::size_t>(selectedPoint))
                                                   : tcbAt(settings, 0);
    const Rational values[3] = {k.tension, k.continuity, k.bias};
    const QString names[3] = {tr("Tension T = %1:"), tr("Continuity C = %1:"), tr("Bias B = %1:")};
    for (std::size_t j = 0; j < 3; ++j) {
        m_tcbLabels[j]->setVisible(kb);
        m_tcbSliders[j]->setVisible(kb);
        m_tcbSliders[j]->setValue(familySliderValue(values[j]));
        m_tcbLabels[j]->setText(names[j].arg(displayText(toString(values[j]))));
    }
    m_knotLabel->setText(allKnots() ? tr("T, C, B of every point:")
                                    : tr("T, C, B of the selected point q%1:").arg(selectedPoint));
    m_resetTangents->setVisible(hermite);
    m_ruleLabel->setVisible(settings.family != CurveFamily::CatmullRom);
    switch (settings.family) {
    case CurveFamily::Cardinal:
        m_ruleLabel->setText(tr("Tangents set by a rule: (1 − c)(qᵢ₊₁ − qᵢ₋₁)/2, Catmull-Rom with τ = (1 − c)/2."));
        break;
    case CurveFamily::KochanekBartels:
        m_ruleLabel->setText(tr("Tangents set by a rule: T scales them, C ≠ 0 makes the incoming and outgoing "
                                "tangents differ (a corner), B leans them towards one chord."));
        break;
    case CurveFamily::Hermite:
        m_ruleLabel->setText(tr("Every tangent is yours: drag the square at its end, or Alt + arrows for the "
                                "selected point's."));
        break;
    default: m_ruleLabel->clear(); break;
    }
    m_showing = false;
}

void FamilyPanel::retranslate()
{
    setTitle(tr("Family: how the tangents are chosen"));
    m_familyLabel->setText(tr("Famil&y:"));
    for (std::size_t i = 0; i < kCurveFamilies.size(); ++i)
        m_familyCombo->setItemText(static_cast<int>(i), curveFamilyName(kCurveFamilies[i]));
    m_familyCombo->setToolTip(tr("Def 2.8 builds each segment from two points and two tangents. Catmull-Rom sets the "
                                 "tangents by the rule τ(qᵢ₊₁ − qᵢ₋₁); cardinal and Kochanek–Bartels by other rules; "
                                 "Hermite lets you drag them; the C² splines solve for them."));
    m_cardinalSlider->setToolTip(tr("The cardinal tension c in steps of 1/20 from −1 to 1: c = 0 is Catmull-Rom's "
                                    "τ = 1/2, c = 1 gives zero tangents (straight segments)."));
    m_allKnots->setText(tr("All points"));
    m_allKnots->setToolTip(tr("Move T, C, B of every point at once (also when no point is selected)."));
    m_tcbSliders[0]->setToolTip(tr("Tension T in steps of 1/20: τ = (1 − T)/2; 1 gives zero tangents."));
    m_tcbSliders[1]->setToolTip(tr("Continuity C in steps of 1/20: 0 keeps the curve C¹ (Prop 2.3); any other value "
                                   "makes the two tangents differ; −1 gives corners."));
    m_tcbSliders[2]->setToolTip(tr("Bias B in steps of 1/20: > 0 leans the tangents towards the incoming chord, < 0 "
                                   "towards the outgoing one."));
    m_resetTangents->setText(tr("Back to the Catmull-Rom tangents"));
    m_resetTangents->setToolTip(tr("Every tangent as the Catmull-Rom rule τ(qᵢ₊₁ − qᵢ₋₁) of the selected τ sets it."));
    showSettings(m_shown, m_selectedPoint);
}

} // namespace granota::ui
