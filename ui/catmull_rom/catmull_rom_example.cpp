#include "ui/catmull_rom/catmull_rom_example.h"

#include <algorithm>
#include <utility>

namespace granota::ui {

std::optional<CatmullRomExampleState> catmullRomExample(const WorkedExample& example, const std::vector<Point>& current,
                                                        const CatmullRomSettings& settings)
{
    if (example.tab != "catmull-rom")
        return std::nullopt;
    CatmullRomSettings s = settings;
    std::vector<Point> points = current;
    s.spacing = CatmullRomSpacing::Uniform;
    s.bezier = false;
    s.spline = false;
    s.catmullRom = true;
    s.controlPoints = true;
    s.splineEnds = SplineEnds::Natural;
    s.compareEnds = false;
    s.allTausInPlot = false;
    auto useTaus = [&s](const std::vector<Rational>& taus) {
        if (taus.empty() || static_cast<int>(taus.size()) > CatmullRomSettings::kMaxTensions)
            return false;
        s.taus = taus;
        // Select τ = 1/2, the usual value (Def 2.8), when the example has it.
        const auto half = std::find(taus.begin(), taus.end(), frac(1, 2));
        s.selectedTau = half != taus.end() ? static_cast<int>(half - taus.begin()) : 0;
        return true;
    };
    if (example.kind == "cubic-spline") { // Ex 2.1
        points = toDouble(example.points);
        useTaus({frac(1, 2)});
        s.ends = CatmullRomEnds::Open;
        s.spline = true;
        // Fig 2.1: Ex 2.1's own spline, whose ends are not natural, alone.
        s.splineEnds = SplineEnds::AsEx21;
        s.catmullRom = false;
    } else if (example.kind == "catmull-rom-segment") { // Ex 2.11
        points = toDouble(example.points);
        if (!useTaus(example.taus))
            return std::nullopt;
        s.ends = CatmullRomEnds::Segment;
    } else if (example.kind == "blending") { // Ex 2.12: the points stay
        if (!useTaus(example.taus))
            return std::nullopt;
        s.allTausInPlot = true;
        s.curvaturePlot = false;                // Ex 2.12 is about the blending functions
    } else if (example.kind == "catmull-rom") { // Ex 2.13
        points = toDouble(example.points);
        if (!useTaus(example.taus))
            return std::nullopt;
        const auto mode = example.modes.empty() ? std::optional<CatmullRomMode>(CatmullRomMode::Open)
                                                : parseCatmullRomMode(example.modes.front());
        if (!mode)
            return std::nullopt;
        s.ends = *mode == CatmullRomMode::Cyclic   ? CatmullRomEnds::Cyclic
                 : *mode == CatmullRomMode::Closed ? CatmullRomEnds::Closed
                                                   : CatmullRomEnds::Open;
        s.compareEnds = example.modes.size() > 1;
    } else {
        return std::nullopt;
    }
    for (const Rational& tau : s.taus)
        if (abs(tau) > CatmullRomSettings::kMaxTensionAbs)
            return std::nullopt;
    if (points.size() < 2 || static_cast<int>(points.size()) > CatmullRomSettings::kMaxPoints)
        return std::nullopt;
    return CatmullRomExampleState{std::move(points), s};
}

} // namespace granota::ui
