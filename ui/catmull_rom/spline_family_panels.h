#pragma once
/// \file spline_family_panels.h
/// The Catmull-Rom tab's controls for its two solved families, in one box under the family
/// selector: the "C² spline in the plane" panel with its example (the frog's outline points,
/// closed) and the "function data" panel with its example (d3-shape #38's data) — each shown
/// only in its family. It owns no settings: it shows the tab's and asks the tab for a change
/// or an example, each one undo step.

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QGroupBox>

#include <vector>

class QPushButton;

namespace granota::ui {

class FunctionDataPanel;
class PlaneSplinePanel;

class SplineFamilyPanels : public QGroupBox {
    Q_OBJECT
public:
    explicit SplineFamilyPanels(QWidget* parent = nullptr);

    /// Shows the panel of settings.family (hides the box in the other families).
    void showState(const CatmullRomSettings& settings, const CatmullRomScene& scene, const std::vector<Point>& points);
    void retranslate();
    PlaneSplinePanel* planePanel() const { return m_plane; }
    FunctionDataPanel* dataPanel() const { return m_data; }
    QPushButton* exampleButton() const { return m_example; }

signals:
    void changeRequested(const granota::ui::CatmullRomSettings& after, const QString& undoText);
    /// Load `points` with `settings` as one undo step named `undoText`.
    void exampleRequested(const std::vector<granota::Point>& points, const granota::ui::CatmullRomSettings& settings,
                          const QString& undoText);
    void refused(const QString& message);

private:
    PlaneSplinePanel* m_plane = nullptr;
    FunctionDataPanel* m_data = nullptr;
    QPushButton* m_example = nullptr;
    CatmullRomSettings m_settings;
};

} // namespace granota::ui
