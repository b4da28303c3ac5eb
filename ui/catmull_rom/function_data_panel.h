#pragma once
/// \file function_data_panel.h
/// The Catmull-Rom tab's controls for the "function data" family (shown only in that
/// family): one check box per curve in its colour, the overshoot's shading, and the small
/// table of each curve's largest overshoot (how far beyond the neighbouring data values, and
/// on which interval), with the data's refusal above it. It owns no settings: it shows the
/// tab's and asks for a change (one undo step each).

#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/function_data_settings.h"

#include <QWidget>

#include <array>
#include <vector>

class QCheckBox;
class QLabel;
class QTableWidget;

namespace granota::ui {

class FunctionDataPanel : public QWidget {
    Q_OBJECT
public:
    explicit FunctionDataPanel(QWidget* parent = nullptr);

    /// Shows `settings`, the refusal and the overshoot table of `scene` on `points`.
    void showSettings(const FunctionDataSettings& settings, const FunctionDataScene& scene, const std::vector<Point>& points);
    void retranslate();
    QCheckBox* curveCheck(FunctionDataCurve curve) const { return m_curveChecks[static_cast<std::size_t>(curve)]; }
    QCheckBox* shadeCheck() const { return m_shadeCheck; }
    QTableWidget* overshootTable() const { return m_table; }
    QLabel* errorLabel() const { return m_error; }

signals:
    void changeRequested(const granota::ui::FunctionDataSettings& after, const QString& undoText);

private:
    void fillTable();

    std::array<QCheckBox*, 4> m_curveChecks{};
    QCheckBox* m_shadeCheck = nullptr;
    QLabel* m_error = nullptr;
    QLabel* m_tableTitle = nullptr;
    QTableWidget* m_table = nullptr;
    FunctionDataSettings m_settings;
    FunctionDataScene m_scene;
    std::vector<Point> m_points;
    bool m_showing = false;
};

} // namespace granota::ui
