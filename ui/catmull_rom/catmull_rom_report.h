#pragma once
/// \file catmull_rom_report.h
/// The exact side panel of the Catmull-Rom tab (docs/tabs.md), as HTML for ExactPanel: the
/// matrix M(τ) of Lemma 2.3, the segment polynomials of Def 2.10 (exact fractions when the
/// points are small rationals and the spacing uniform: Ex 2.11 and Ex 2.13 as printed), the
/// tangents at the knots (Prop 2.3), the blending functions (Cor 2.1), Processing's
/// curveTightness, and the comparisons of §2.3 (Bézier C^∞, Catmull-Rom C¹, cubic spline C²)
/// with Ex 2.1's printed pieces checked. Values come from the core (the scene and the
/// CatmullRomAnalysis of catmull_rom_analysis.h, each computed once per change); this only
/// formats them.

#include "core/curves/splines/catmull_rom_analysis.h"
#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QCoreApplication>
#include <QString>

#include <vector>

namespace granota::ui {

class CatmullRomReport {
    Q_DECLARE_TR_FUNCTIONS(CatmullRomReport)
public:
    static constexpr int kMaxListedSegments = 24; ///< per τ; longer curves are summarised

    /// `analysis`: computeAnalysis() of the same points and settings (the exact side, computed once).
    static QString html(const std::vector<Point>& points, const CatmullRomSettings& settings, const CatmullRomScene& scene,
                        const CatmullRomAnalysis& analysis);
    /// "open (Def 2.10, option 2)" … in the user's language.
    static QString endsName(CatmullRomEnds ends);
    /// "natural ends", "the ends of Ex 2.1"…: the cubic spline's end conditions, translated.
    static QString splineEndsName(SplineEnds ends);
};

} // namespace granota::ui
