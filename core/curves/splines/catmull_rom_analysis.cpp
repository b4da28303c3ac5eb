#include "core/curves/splines/catmull_rom_analysis.h"

#include "core/curves/splines/function_spline_segments.h"

#include <algorithm>

namespace granota {

const CatmullRomAnalysis::Curve* CatmullRomAnalysis::selected(int selectedTau) const
{
    if (ends.empty() || selectedTau < 0 || selectedTau >= static_cast<int>(ends.front().curves.size()))
        return nullptr;
    const Curve& c = ends.front().curves[static_cast<std::size_t>(selectedTau)];
    return c.segments ? &c : nullptr;
}

int CatmullRomAnalysis::selectedOrder() const
{
    if (selectedBezier.empty() && selectedKnots.empty())
        return -1;
    int order = 2;
    for (const auto& k : selectedKnots)
        order = std::min(order, k.parametricOrder());
    return order;
}

CatmullRomAnalysis analyseCatmullRom(const std::optional<std::vector<RPoint>>& points, const CatmullRomQuestion& question)
{
    CatmullRomAnalysis a;
    a.points = points;
    if (!points)
        return a;
    if (question.uniform) {
        a.exactCurves = true;
        std::vector<CatmullRomEnds> modes{question.ends};
        if (question.compareEnds)
            modes.push_back(comparedEnds(question.ends));
        for (const CatmullRomEnds ends : modes) {
            CatmullRomAnalysis::EndsCurves e;
            e.ends = ends;
            for (const Rational& tau : question.taus) // Def 2.10, Lemma 2.3
                e.curves.push_back({tau, exactCurveSegments(*points, tau, ends)});
            a.ends.push_back(std::move(e));
        }
        if (const auto* c = a.selected(question.selectedTau)) { // §2.3, Prop 2.3
            a.selectedBezier = bezierSegments(*c->segments);
            a.selectedKnots = knotContinuity(*c->segments, {}, question.ends == CatmullRomEnds::Closed);
        }
    }
    if (question.spline) { // Def 2.3, solved once
        a.spline = cubicSpline(*points, question.splineEnds);
        if (*a.spline) {
            const auto& s = a.spline->value();
            a.splineCheck = checkContinuity(s, kSplineCheckedOrder, *points);
            const auto graph = functionSplineSegments(s);
            a.splineBezier = bezierSegments(graph.segments);
            a.splineKnots = knotContinuity(graph.segments, graph.intervals);
        }
    }
    return a;
}

} // namespace granota
