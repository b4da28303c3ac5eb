#pragma once
/// \file fit_settings_panel.h
/// The Fitting tab's "Least-squares fit" group (§2.1.3): the fields of its settings
/// (fit_settings.h: the degree n, the parameters t_i, the solver, the parameter correction),
/// the Import button, the matrices of the exact panel, and the curvature comb with its scale.
/// It builds, words and fills the fields; the tab connects them (each change one undo step).
/// Its texts keep the tab's translation context (granota::ui::FitTab), so the translations still match.

#include "ui/fit/fit_settings.h"

#include <QGroupBox>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace granota::ui {

class CurvatureCombScaleBox;
class FitDegreeBox;

class FitSettingsPanel : public QGroupBox {
public:
    explicit FitSettingsPanel(QWidget* parent);

    /// Fills the fields with `s` for k + 1 data points (the degree's maximum is min(k, kMaxFitDegree)).
    void showSettings(const FitSettings& s, int k, int fittedDegree);
    void retranslate();

    FitDegreeBox* degreeBox() const { return m_degree; }
    QComboBox* parametrizationBox() const { return m_parametrization; }
    QComboBox* solverBox() const { return m_solver; }
    QCheckBox* correctionBox() const { return m_correct; }
    QSpinBox* iterationsBox() const { return m_iterations; }
    QPushButton* importButton() const { return m_import; }
    QCheckBox* showMatricesBox() const { return m_showMatrices; }
    QCheckBox* combBox() const { return m_combBox; }
    CurvatureCombScaleBox* combScaleBox() const { return m_combScaleBox; }

private:
    QLabel* m_degreeLabel = nullptr;
    FitDegreeBox* m_degree = nullptr;
    QLabel* m_parametrizationLabel = nullptr;
    QComboBox* m_parametrization = nullptr;
    QLabel* m_solverLabel = nullptr;
    QComboBox* m_solver = nullptr;
    QCheckBox* m_correct = nullptr;
    QSpinBox* m_iterations = nullptr;
    QPushButton* m_import = nullptr;
    QCheckBox* m_showMatrices = nullptr;
    QCheckBox* m_combBox = nullptr;
    CurvatureCombScaleBox* m_combScaleBox = nullptr;
};

} // namespace granota::ui
