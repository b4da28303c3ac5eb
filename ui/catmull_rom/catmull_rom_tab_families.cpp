// The Catmull-Rom tab's family selector (issue 37): the family box, the Hermite handles and
// the undoable edits of the family's settings. The rest of the tab is catmull_rom_tab.cpp.
#include "ui/catmull_rom/catmull_rom_tab.h"

#include "ui/catmull_rom/conventions_table.h"
#include "ui/catmull_rom/family_curves.h"
#include "ui/catmull_rom/family_panel.h"
#include "ui/catmull_rom/hermite_handles.h"
#include "ui/catmull_rom/knot_continuity_table.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"

#include "core/curves/splines/cardinal_spline.h"

#include <QTabWidget>

#include <algorithm>

namespace granota::ui {

namespace {

constexpr int kFamilyMergeIdBase = 0x4b420000; ///< "KB": the merge ids of the family's sliders

} // namespace

void CatmullRomTab::buildFamilyControls()
{
    m_familyPanel = new FamilyPanel(this);
    connect(m_familyPanel, &FamilyPanel::familyChosen, this, &CatmullRomTab::setFamily);
    connect(m_familyPanel, &FamilyPanel::cardinalTensionChosen, this, &CatmullRomTab::setCardinalTension);
    connect(m_familyPanel, &FamilyPanel::tcbChosen, this, &CatmullRomTab::setTcb);
    connect(m_familyPanel, &FamilyPanel::resetTangentsAsked, this, &CatmullRomTab::resetHermiteTangents);
    connect(m_editor, &PointEditor::pointInserted, this, &CatmullRomTab::pointInserted);
    connect(m_editor, &PointEditor::pointRemoved, this, &CatmullRomTab::pointRemoved);
    connect(m_editor, &PointEditor::selectionChanged, this,
            [this](int index) { m_familyPanel->showSettings(m_settings, index); });
    // Installed after the point editor: its handles are picked before the points.
    m_hermiteHandles = new HermiteHandles(m_canvas, m_editor, this);
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform& v, const CanvasStyle& s) { m_hermiteHandles->draw(p, v, s); });
    connect(m_hermiteHandles, &HermiteHandles::tangentDragged, this, &CatmullRomTab::hermiteTangentDragged);
    connect(m_hermiteHandles, &HermiteHandles::dragFinished, this, &CatmullRomTab::hermiteDragFinished);
    connect(m_hermiteHandles, &HermiteHandles::tangentNudged, this, &CatmullRomTab::setHermiteTangent);
}

void CatmullRomTab::addFamilySideTabs()
{
    m_knotTable = new KnotContinuityTable(this);
    m_sideTabs->addTab(m_knotTable, QString());
    m_conventions = new ConventionsTable(this);
    m_sideTabs->addTab(m_conventions, QString());
}

void CatmullRomTab::retranslateFamilyControls()
{
    m_familyPanel->retranslate();
    m_knotTable->retranslate();
    m_sideTabs->setTabText(m_sideTabs->indexOf(m_knotTable), tr("Knots"));
    m_sideTabs->setTabToolTip(m_sideTabs->indexOf(m_knotTable), m_knotTable->toolTip());
    m_conventions->retranslate();
    m_sideTabs->setTabText(m_sideTabs->indexOf(m_conventions), tr("Conventions"));
    m_sideTabs->setTabToolTip(m_sideTabs->indexOf(m_conventions), m_conventions->toolTip());
}

void CatmullRomTab::updateFamilyViews()
{
    const bool hermite = m_settings.family == CurveFamily::Hermite;
    m_hermiteHandles->setState(hermite, m_editor->points(),
                               hermite ? hermiteTangentsOf(m_editor->points(), m_settings) : std::vector<Point>{});
    // The τ of the curve shown, in every source's convention.
    Rational tau = frac(1, 2);
    if (m_settings.family == CurveFamily::Cardinal)
        tau = cardinalTau(m_settings.cardinalTension);
    else if (m_settings.family == CurveFamily::KochanekBartels)
        tau = cardinalTau(tcbAt(m_settings, static_cast<std::size_t>(std::max(0, m_editor->selected()))).tension);
    else if (m_settings.selectedTau >= 0 && m_settings.selectedTau < static_cast<int>(m_settings.taus.size()))
        tau = m_settings.taus[static_cast<std::size_t>(m_settings.selectedTau)];
    m_conventions->showTau(tau);
    // The knots of the family's curve, or of the selected τ's Catmull-Rom curve (Prop 2.3).
    const int n = static_cast<int>(m_editor->points().size());
    const bool closed = m_settings.ends == CatmullRomEnds::Closed;
    const int first = firstSegmentStart(m_settings.ends);
    if (m_settings.family != CurveFamily::CatmullRom) {
        m_knotTable->showCurve(m_scene.family.segments, m_scene.family.intervals, closed, first, n);
    } else if (m_settings.selectedTau >= 0 && m_settings.selectedTau < static_cast<int>(m_scene.curves.size())) {
        const CatmullRomCurve& c = m_scene.curves[static_cast<std::size_t>(m_settings.selectedTau)];
        m_knotTable->showCurve(c.segments, c.intervals, closed, first, n);
    } else {
        m_knotTable->showCurve({}, {}, false, 0, n);
    }
}

void CatmullRomTab::setFamily(CurveFamily family)
{
    CatmullRomSettings after = m_settings;
    after.family = family;
    // Def 2.8 as one choice of tangents: Hermite starts from the Catmull-Rom tangents (once;
    // tangents the student set are kept when the family is left and chosen again).
    if (family == CurveFamily::Hermite && after.hermiteTangents.size() != m_editor->points().size())
        after.hermiteTangents = hermiteTangentsOf(m_editor->points(), after);
    changeSettings(after, tr("Family: %1").arg(curveFamilyName(family)));
}

void CatmullRomTab::setCardinalTension(const Rational& c)
{
    CatmullRomSettings after = m_settings;
    after.cardinalTension = c;
    changeSettings(after, tr("Change the cardinal tension"), false, kFamilyMergeIdBase);
}

void CatmullRomTab::setTcb(int which, const Rational& value)
{
    if (which < 0 || which > 2)
        return;
    CatmullRomSettings after = m_settings;
    const std::size_t n = m_editor->points().size();
    if (after.tcb.size() < n)
        after.tcb.resize(n);
    const int selected = m_editor->selected();
    const bool all = m_familyPanel->allKnots() || selected < 0 || selected >= static_cast<int>(n);
    for (std::size_t i = 0; i < after.tcb.size(); ++i) {
        if (!all && static_cast<int>(i) != selected)
            continue;
        Rational& v = which == 0 ? after.tcb[i].tension : which == 1 ? after.tcb[i].continuity : after.tcb[i].bias;
        v = value;
    }
    const QString names[3] = {tr("Change T"), tr("Change C"), tr("Change B")};
    // Moves of one slider on one point (or on all) merge into one step.
    changeSettings(after, names[which], false, kFamilyMergeIdBase + 1 + which * 1024 + (all ? 1023 : selected));
}

void CatmullRomTab::setHermiteTangent(int index, Point tangent)
{
    CatmullRomSettings after = m_settings;
    after.hermiteTangents = hermiteTangentsOf(m_editor->points(), after);
    if (index < 0 || index >= static_cast<int>(after.hermiteTangents.size()) || !isFinite(tangent))
        return;
    after.hermiteTangents[static_cast<std::size_t>(index)] = tangent;
    changeSettings(after, tr("Move the tangent at q%1").arg(index));
}

void CatmullRomTab::resetHermiteTangents()
{
    CatmullRomSettings after = m_settings;
    after.hermiteTangents.clear();
    after.hermiteTangents = hermiteTangentsOf(m_editor->points(), after);
    changeSettings(after, tr("Back to the Catmull-Rom tangents"));
}

void CatmullRomTab::hermiteTangentDragged(int index, Point tangent)
{
    // Live, without an undo step: the step is pushed when the drag ends.
    m_settings.hermiteTangents = hermiteTangentsOf(m_editor->points(), m_settings);
    if (index < 0 || index >= static_cast<int>(m_settings.hermiteTangents.size()))
        return;
    m_settings.hermiteTangents[static_cast<std::size_t>(index)] = tangent;
    recompute();
}

void CatmullRomTab::hermiteDragFinished(int index, Point startTangent)
{
    const CatmullRomSettings after = m_settings;
    if (index < 0 || index >= static_cast<int>(m_settings.hermiteTangents.size()))
        return;
    m_settings.hermiteTangents[static_cast<std::size_t>(index)] = startTangent; // the step goes from the start
    if (after == m_settings)
        return;
    changeSettings(after, tr("Drag the tangent at q%1").arg(index));
}

void CatmullRomTab::pointInserted(int index)
{
    // The values are stored by index: those from `index` on belong to the points that moved up
    // one. Points past the end of a list take the defaults anyway (tcbAt, hermiteTangentsOf).
    if (index < 0)
        return;
    CatmullRomSettings after = m_settings;
    const auto at = static_cast<std::size_t>(index);
    if (at < after.tcb.size())
        after.tcb.insert(after.tcb.begin() + index, TcbKnot<Rational>{});
    if (at < after.hermiteTangents.size()) {
        // The rule's tangent with the new neighbours (the points have changed already).
        const std::vector<Point> rule = catmullRomTangents(m_editor->points(), m_settings);
        after.hermiteTangents.insert(after.hermiteTangents.begin() + index, at < rule.size() ? rule[at] : Point{0, 0});
    }
    changeSettings(after, QString()); // inside the editor's step, which names it
}

void CatmullRomTab::pointRemoved(int index)
{
    if (index < 0)
        return;
    CatmullRomSettings after = m_settings;
    const auto at = static_cast<std::size_t>(index);
    if (at < after.tcb.size())
        after.tcb.erase(after.tcb.begin() + index);
    if (at < after.hermiteTangents.size())
        after.hermiteTangents.erase(after.hermiteTangents.begin() + index);
    changeSettings(after, QString()); // inside the editor's step, which names it
}

} // namespace granota::ui
