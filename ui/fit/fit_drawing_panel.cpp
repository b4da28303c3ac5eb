#include "ui/fit/fit_drawing_panel.h"

#include <QCoreApplication>
#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>

namespace granota::ui {

namespace {
constexpr int kSamplesMergeId = 0x46540002; ///< "FT": the samples spin box held down is one step
} // namespace

FitDrawingPanel::FitDrawingPanel(std::function<const FitDisplay&()> current,
                                 std::function<void(const FitDisplay&, const QString&, int)> change, QWidget* parent)
    : QGroupBox(parent), m_current(std::move(current)), m_change(std::move(change))
{
    auto* display = new QFormLayout(this);
    display->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    display->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_controlPointsBox = new QCheckBox(this);
    m_residualsBox = new QCheckBox(this);
    m_breakdownBox = new QCheckBox(this);
    m_allParametrizationsBox = new QCheckBox(this);
    m_samplesLabel = new QLabel(this);
    m_samplesBox = new QSpinBox(this);
    m_samplesBox->setRange(FitDisplay::kMinSamples, FitDisplay::kMaxSamples);
    m_samplesBox->setKeyboardTracking(false);
    m_samplesLabel->setBuddy(m_samplesBox);
    auto* toggles = new QHBoxLayout;
    toggles->addWidget(m_controlPointsBox);
    toggles->addWidget(m_residualsBox);
    toggles->addStretch(1);
    display->addRow(toggles);
    display->addRow(m_breakdownBox);
    display->addRow(m_samplesLabel, m_samplesBox);
    display->addRow(m_allParametrizationsBox);
    const auto toggle = [this](QCheckBox* box, bool FitDisplay::*flag, const char* undoText) {
        connect(box, &QCheckBox::toggled, this, [this, flag, undoText](bool on) {
            if (m_updating)
                return;
            FitDisplay after = m_current();
            after.*flag = on;
            m_change(after, QCoreApplication::translate("granota::ui::FitTab", undoText), -1);
        });
    };
    toggle(m_controlPointsBox, &FitDisplay::controlPoints, QT_TRANSLATE_NOOP("granota::ui::FitTab", "Control points"));
    toggle(m_residualsBox, &FitDisplay::residuals, QT_TRANSLATE_NOOP("granota::ui::FitTab", "Residuals"));
    toggle(m_breakdownBox, &FitDisplay::breakdown, QT_TRANSLATE_NOOP("granota::ui::FitTab", "Step by step"));
    toggle(m_allParametrizationsBox, &FitDisplay::errorPlotAllParametrizations,
           QT_TRANSLATE_NOOP("granota::ui::FitTab", "Every parametrization in the plot"));
    connect(m_samplesBox, qOverload<int>(&QSpinBox::valueChanged), this, [this](int part) {
        if (m_updating)
            return;
        FitDisplay after = m_current();
        after.samples = part;
        m_change(after, QCoreApplication::translate("granota::ui::FitTab", "Samples: %1").arg(part), kSamplesMergeId);
    });
}

void FitDrawingPanel::setDisplay(const FitDisplay& d)
{
    m_updating = true;
    m_controlPointsBox->setChecked(d.controlPoints);
    m_residualsBox->setChecked(d.residuals);
    m_breakdownBox->setChecked(d.breakdown);
    m_samplesBox->setValue(d.samples);
    m_allParametrizationsBox->setChecked(d.errorPlotAllParametrizations);
    m_updating = false;
}

void FitDrawingPanel::retranslate()
{
    setTitle(QCoreApplication::translate("granota::ui::FitTab", "Drawing"));
    m_controlPointsBox->setText(QCoreApplication::translate("granota::ui::FitTab", "Con&trol points"));
    m_controlPointsBox->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Draw the fitted control points Pⱼ (squares), their labels and the control "
                               "polygon. The thesis's Figs 2.5–2.8 show the curve and the data alone."));
    m_residualsBox->setText(QCoreApplication::translate("granota::ui::FitTab", "&Residuals"));
    m_residualsBox->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Draw the segments from α(tᵢ) to each data point Qᵢ: the errors the fit minimises."));
    m_breakdownBox->setText(QCoreApplication::translate("granota::ui::FitTab", "Step by st&ep"));
    m_breakdownBox->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Also draw the Bézier curves of the first 1, 2, …, n+1 fitted control points, thinner "
                               "and lighter, like the desglossar option of the thesis's Matlab Rep_BezParamEqui and "
                               "Rep_BezParamProp (Annex III)."));
    m_samplesLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "Samp&les:"));
    const QString samplesTip = QCoreApplication::translate(
        "granota::ui::FitTab", "Sampling precision: the fitted curve is drawn through this many intervals of t, like "
                               "part in the thesis's Matlab Rep_BezParamEqui(Q, n, part, desglossar).");
    m_samplesLabel->setToolTip(samplesTip);
    m_samplesBox->setToolTip(samplesTip);
    m_allParametrizationsBox->setText(
        QCoreApplication::translate("granota::ui::FitTab", "Every parametri&zation in the error plot"));
    m_allParametrizationsBox->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Plot the error against the degree for uniform, chord-length, centripetal and "
                               "Annex III parameters at once, one line each, to see where each wins."));
}

} // namespace granota::ui
