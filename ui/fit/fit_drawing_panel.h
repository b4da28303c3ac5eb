#pragma once
/// \file fit_drawing_panel.h
/// The Fitting tab's "Drawing" group: what is drawn of the fit (fit_display.h), the thesis's
/// Matlab options of Annex III (the control points `puntsvis`, the curves step by step
/// `desglossar`, the samples `part`), the residuals, and the error plot's lines for every
/// parametrization. Each change is handed to the tab, which makes it one undo step.
/// Its texts keep the tab's translation context (granota::ui::FitTab), so the translations still match.

#include "ui/fit/fit_display.h"

#include <QGroupBox>
#include <QString>

#include <functional>

class QCheckBox;
class QLabel;
class QSpinBox;

namespace granota::ui {

class FitDrawingPanel : public QGroupBox {
public:
    /// `change(after, undoText, mergeId)` is called with a changed copy of `current()` (mergeId
    /// ≥ 0: successive changes with it merge, a spin box held down).
    FitDrawingPanel(std::function<const FitDisplay&()> current,
                    std::function<void(const FitDisplay&, const QString&, int)> change, QWidget* parent);

    /// Shows `d` without calling `change`.
    void setDisplay(const FitDisplay& d);
    void retranslate();

    QCheckBox* controlPointsBox() const { return m_controlPointsBox; }
    QCheckBox* residualsBox() const { return m_residualsBox; }
    QCheckBox* breakdownBox() const { return m_breakdownBox; }
    QSpinBox* samplesBox() const { return m_samplesBox; }
    QCheckBox* allParametrizationsBox() const { return m_allParametrizationsBox; }

private:
    std::function<const FitDisplay&()> m_current;
    std::function<void(const FitDisplay&, const QString&, int)> m_change;
    bool m_updating = false; ///< setDisplay() is filling the fields
    QCheckBox* m_controlPointsBox = nullptr;
    QCheckBox* m_residualsBox = nullptr;
    QCheckBox* m_breakdownBox = nullptr;
    QLabel* m_samplesLabel = nullptr;
    QSpinBox* m_samplesBox = nullptr;
    QCheckBox* m_allParametrizationsBox = nullptr;
};

} // namespace granota::ui
