// The Catmull-Rom tab's documents and exports: the worked examples, the document's settings
// and the refusals of its points, the CSV and the TikZ picture (catmull_rom_export.h). The
// rest of the tab is catmull_rom_tab.cpp and catmull_rom_tab_families.cpp.
#include "ui/catmull_rom/catmull_rom_tab.h"

#include "core/io/worked_examples.h"
#include "ui/catmull_rom/catmull_rom_example.h"
#include "ui/catmull_rom/catmull_rom_export.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"

#include <QUndoStack>

namespace granota::ui {

// ---------------------------------------------------------------- examples and documents

bool CatmullRomTab::loadExample(const WorkedExample& example)
{
    const auto state = catmullRomExample(example, m_editor->points(), m_settings);
    if (!state)
        return false;
    loadPointsAndSettings(state->points, state->settings, tr("Load Ex %1").arg(QString::fromStdString(example.id)));
    return true;
}

void CatmullRomTab::loadPointsAndSettings(const std::vector<Point>& points, const CatmullRomSettings& settings,
                                          const QString& undoText)
{
    m_undo->beginMacro(undoText);
    if (points != m_editor->points())
        m_editor->setPoints(points, undoText);
    changeSettings(settings, undoText);
    m_undo->endMacro();
    updateContentBounds(true);
    m_canvas->fitToContent();
}

void CatmullRomTab::writeSettings(QJsonObject& state) const { ui::writeSettings(m_settings, state); }

PointListMessages CatmullRomTab::pointMessages() const
{
    PointListMessages say;
    say.notAList = tr("The Catmull-Rom points are missing or not a list.");
    say.badCount = [](int count) {
        return tr("A Catmull-Rom curve needs between 2 and %1 points; the file has %2.")
            .arg(CatmullRomSettings::kMaxPoints)
            .arg(count);
    };
    say.notAPair = [](int i) { return tr("Point %1 of the Catmull-Rom tab is not a pair of numbers.").arg(i); };
    say.notFinite = [](int i) { return tr("Point %1 of the Catmull-Rom tab is not a finite number.").arg(i); };
    return say;
}

bool CatmullRomTab::loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error)
{
    QString problem;
    const auto settings = readSettings(state, &problem);
    if (!settings) {
        error = tr("The Catmull-Rom settings are not valid (“%1”): tensions must be numbers in [−10, 10], "
                   "at most %2 of them, without repeats.")
                    .arg(problem)
                    .arg(CatmullRomSettings::kMaxTensions);
        return false;
    }
    // All checked: now change the tab.
    m_editor->applyPoints(points);
    applySettings(*settings);
    return true;
}

// ---------------------------------------------------------------- exports

QString CatmullRomTab::csv() const { return catmullRomCsv(m_editor->points(), m_editor->exactPoints(), m_settings, m_scene); }

void CatmullRomTab::drawTikz(TikzWriter& w) const
{
    writeCatmullRomTikz(w, m_editor->points(), m_editor->polygonVisible(), m_settings, m_scene);
}

} // namespace granota::ui
