#include "ui/fit/fit_settings_panel.h"

#include "ui/common/curvature_comb_scale_box.h"
#include "ui/fit/fit_degree_box.h"

#include <QCoreApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>

namespace granota::ui {

namespace {

/// A combo box that never truncates its items (in Catalan, in presentation mode): when the
/// side panel is narrow, the form wraps its label above it instead.
class WholeComboBox : public QComboBox {
public:
    using QComboBox::QComboBox;
    QSize minimumSizeHint() const override { return sizeHint(); }
};

} // namespace

FitSettingsPanel::FitSettingsPanel(QWidget* parent) : QGroupBox(parent)
{
    auto* form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // narrow (presentation, Catalan): labels above the fields
    m_degree = new FitDegreeBox(this);
    m_degree->setRange(0, kMaxFitDegree);
    m_degreeLabel = new QLabel(this);
    m_degreeLabel->setBuddy(m_degree);
    form->addRow(m_degreeLabel, m_degree);
    m_parametrization = new WholeComboBox(this);
    m_parametrization->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (Parametrization p :
         {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal, Parametrization::AnnexIII})
        m_parametrization->addItem(QString(), static_cast<int>(p));
    m_parametrizationLabel = new QLabel(this);
    m_parametrizationLabel->setBuddy(m_parametrization);
    form->addRow(m_parametrizationLabel, m_parametrization);
    m_solver = new WholeComboBox(this);
    m_solver->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (LeastSquaresSolver s : {LeastSquaresSolver::Qr, LeastSquaresSolver::Normal, LeastSquaresSolver::Svd})
        m_solver->addItem(QString(), static_cast<int>(s));
    m_solverLabel = new QLabel(this);
    m_solverLabel->setBuddy(m_solver);
    form->addRow(m_solverLabel, m_solver);
    m_correct = new QCheckBox(this);
    m_iterations = new QSpinBox(this);
    m_iterations->setRange(1, FitSettings::kMaxIterations);
    form->addRow(m_correct, m_iterations);
    auto* buttons = new QHBoxLayout;
    m_import = new QPushButton(this);
    m_showMatrices = new QCheckBox(this);
    buttons->addWidget(m_import);
    buttons->addWidget(m_showMatrices);
    buttons->addStretch(1);
    form->addRow(buttons);
    // The comb and its scale, as the correction and its count: a row of their own.
    m_combBox = new QCheckBox(this);
    m_combScaleBox = new CurvatureCombScaleBox(this);
    m_combScaleBox->setEnabled(false);
    form->addRow(m_combBox, m_combScaleBox);
}

void FitSettingsPanel::showSettings(const FitSettings& s, int k, int fittedDegree)
{
    m_degree->setMaximum(std::clamp(k, 0, kMaxFitDegree));
    m_degree->setValue(fittedDegree);
    m_parametrization->setCurrentIndex(m_parametrization->findData(static_cast<int>(s.parametrization)));
    m_solver->setCurrentIndex(m_solver->findData(static_cast<int>(s.solver)));
    m_correct->setChecked(s.correctParameters);
    m_iterations->setValue(std::clamp(s.iterations, 1, FitSettings::kMaxIterations));
    m_iterations->setEnabled(s.correctParameters);
}

void FitSettingsPanel::retranslate()
{
    setTitle(QCoreApplication::translate("granota::ui::FitTab", "Least-squares fit (§2.1.3)"));
    m_degreeLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "&Degree n:"));
    m_degree->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "n: the fitted Bézier curve has n + 1 control points P₀…Pₙ, so n + 1 ≤ k + 1 data "
                               "points (§2.1.3, Lemma 2.2). Ex 2.7 uses n = 2, Ex 2.8 n = 3."));
    m_parametrizationLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "&Parameters tᵢ:"));
    m_parametrization->setItemText(0, QCoreApplication::translate("granota::ui::FitTab", "Uniform, i/k (Ex 2.7, 2.8)"));
    m_parametrization->setItemText(1, QCoreApplication::translate("granota::ui::FitTab", "Chord length (Ex 2.9, 2.10)"));
    m_parametrization->setItemText(2, QCoreApplication::translate("granota::ui::FitTab", "Centripetal (beyond the thesis)"));
    m_parametrization->setItemText(3, QCoreApplication::translate("granota::ui::FitTab", "Annex III (BezParamProp)"));
    m_parametrization->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord "
                               "lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); centripetal, proportional to √dᵢ; or as Annex III's BezParamProp "
                               "computes them, with |Qᵢ₋₁| in place of dᵢ (how Figs 2.7 and 2.8 were drawn)."));
    m_solverLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "&Solver:"));
    m_solver->setItemText(0, QCoreApplication::translate("granota::ui::FitTab", "QR (default)"));
    m_solver->setItemText(1, QCoreApplication::translate("granota::ui::FitTab", "Normal equations (the thesis)"));
    m_solver->setItemText(2, QCoreApplication::translate("granota::ui::FitTab", "SVD (singular values)"));
    m_solver->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "How MP = Q is solved in the least-squares sense. The thesis solves the normal "
                               "equations MᵀM P = MᵀQ (Prop 2.2), which square the condition number; QR and SVD "
                               "work on M itself and stay accurate at high degree."));
    m_correct->setText(QCoreApplication::translate("granota::ui::FitTab", "&Correct parameters, at most"));
    m_correct->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Beyond the thesis: project each Qᵢ onto the fitted curve, take the new tᵢ and fit "
                               "again, while the error Σ‖Qᵢ − α(tᵢ)‖² drops."));
    m_iterations->setSuffix(QCoreApplication::translate("granota::ui::FitTab", " times"));
    m_iterations->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "The largest number of parameter corrections (re-projection and refit)."));
    m_import->setText(QCoreApplication::translate("granota::ui::FitTab", "&Import CSV…"));
    m_import->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Read the data points Qᵢ from a CSV file (one “x,y” per line) or a JSON list [[x,y],…]."));
    m_showMatrices->setText(QCoreApplication::translate("granota::ui::FitTab", "Show &matrices"));
    m_combBox->setText(QCoreApplication::translate("granota::ui::FitTab", "Curvature com&b"));
    m_combBox->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab",
        "The curvature comb of the fitted curve (beyond the thesis): teeth along the normal as long "
        "as |κ| times the scale in the key, and the line through their tips; where the comb wiggles, so does the fit."));
    m_combScaleBox->retranslate();
    m_showMatrices->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Show M (Lemma 2.2), MᵀM, (MᵀM)⁻¹ and M⁺ = (MᵀM)⁻¹Mᵀ (Note 2.2), in fractions "
                               "when the data and the parameters are rational, as in Ex 2.7 and Ex 2.8."));
}

} // namespace granota::ui
