#pragma once
/// \file plane_spline_panel.h
/// The Catmull-Rom tab's controls for the "C² spline in the plane" family (shown only in
/// that family): the end conditions, the parameters, the two end tangents of clamped ends
/// (x and y each an exact number, as typed) and the Catmull-Rom comparison, with the
/// spline's refusal under them. It owns no settings: it shows the tab's and asks for a change
/// (one undo step each).

#include "ui/catmull_rom/plane_spline_curves.h"
#include "ui/catmull_rom/plane_spline_settings.h"

#include <QWidget>

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;

namespace granota::ui {

class PlaneSplinePanel : public QWidget {
    Q_OBJECT
public:
    explicit PlaneSplinePanel(QWidget* parent = nullptr);

    /// Shows `settings` and the scene's refusal without asking for anything.
    void showSettings(const PlaneSplineSettings& settings, const PlaneSplineScene& scene);
    void retranslate();
    QComboBox* endsCombo() const { return m_endsCombo; }
    QComboBox* parametersCombo() const { return m_parametersCombo; }
    /// Start x, start y, end x, end y.
    const std::array<QLineEdit*, 4>& tangentEdits() const { return m_tangentEdits; }
    QCheckBox* catmullRomCheck() const { return m_catmullRomCheck; }
    QLabel* errorLabel() const { return m_error; }

signals:
    /// The person asks for `after`; `undoText` names the step.
    void changeRequested(const granota::ui::PlaneSplineSettings& after, const QString& undoText);
    /// A typed tangent is refused (the shown one is put back).
    void refused(const QString& message);

private:
    void tangentTyped();

    QLabel* m_endsLabel = nullptr;
    QComboBox* m_endsCombo = nullptr;
    QLabel* m_parametersLabel = nullptr;
    QComboBox* m_parametersCombo = nullptr;
    QLabel* m_startLabel = nullptr;
    QLabel* m_endLabel = nullptr;
    std::array<QLineEdit*, 4> m_tangentEdits{};
    QCheckBox* m_catmullRomCheck = nullptr;
    QLabel* m_error = nullptr;
    PlaneSplineSettings m_settings;
    bool m_showing = false;
};

} // namespace granota::ui
