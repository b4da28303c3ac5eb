#include "ui/catmull_rom/family_panel.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>

namespace granota::ui {

FamilyPanel::FamilyPanel(QWidget* parent) : QGroupBox(parent)
{
    m_familyLabel = new QLabel(this);
    m_familyCombo = new QComboBox(this);
    for (CurveFamily f : kCurveFamilies)
        m_familyCombo->addItem(QString(), curveFamilyKey(f));
    m_familyLabel->setBuddy(m_familyCombo);
    auto* layout = new QGridLayout(this);
    layout->addWidget(m_familyLabel, 0, 0);
    layout->addWidget(m_familyCombo, 0, 1);
    layout->setColumnStretch(1, 1);
    connect(m_familyCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!m_showing && i >= 0 && i < static_cast<int>(kCurveFamilies.size()))
            emit familyChosen(kCurveFamilies[static_cast<std::size_t>(i)]);
    });
}

void FamilyPanel::showSettings(const CatmullRomSettings& settings)
{
    m_showing = true;
    for (std::size_t i = 0; i < kCurveFamilies.size(); ++i)
        if (kCurveFamilies[i] == settings.family)
            m_familyCombo->setCurrentIndex(static_cast<int>(i));
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
}

} // namespace granota::ui
