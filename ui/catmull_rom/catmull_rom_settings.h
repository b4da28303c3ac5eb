#pragma once
/// \file catmull_rom_settings.h
/// Everything the Catmull-Rom tab shows besides its points: the tensions τ, the end mode of
/// Def 2.10, the knot spacing and the comparisons of §2.3. A plain value, so that an undo
/// step can hold the settings before and after, and the document can save them.

#include "core/curves/splines/catmull_rom_ends.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/kochanek_bartels.h"
#include "core/exact/rational.h"
#include "ui/catmull_rom/curve_family.h"
#include "ui/catmull_rom/function_data_settings.h"
#include "ui/catmull_rom/plane_spline_settings.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

/// Knot spacing h_i = |q_{i+1} − q_i|^α: the thesis's uniform spacing and two beyond it.
enum class CatmullRomSpacing { Uniform, Centripetal, Chordal };

struct CatmullRomSettings {
    static constexpr int kMaxTensions = 10;   ///< drawn at once (each in the colour of its value: tension_colour.h)
    static constexpr int kMaxTensionAbs = 10; ///< docs/extreme-cases.md: τ ∈ [−10, 10]
    static constexpr int kMaxPoints = 200;    ///< docs/extreme-cases.md (soft bodies up to 200 sides)

    static constexpr int kTcbSteps = 20; ///< T, C, B and the cardinal c move in steps of 1/20 in [−1, 1] (exact)

    CurveFamily family = CurveFamily::CatmullRom; ///< which curves go through the points (curve_family.h)
    Rational cardinalTension{0}; ///< c ∈ [−1, 1] of the cardinal family, τ = (1 − c)/2 (cardinal_spline.h)
    /// Kochanek–Bartels T, C, B per point, each in [−1, 1] (kochanek_bartels.h); missing points are (0, 0, 0).
    std::vector<TcbKnot<Rational>> tcb;
    /// The Hermite family's tangent at each point, p′ in the local s (Def 2.8); missing points
    /// take the Catmull-Rom tangent τ(q_{i+1} − q_{i−1}) of the selected τ.
    std::vector<Point> hermiteTangents;
    std::vector<Rational> taus{Rational(0), frac(1, 2), Rational(2)}; ///< Ex 2.11's tensions
    int selectedTau = 1;                                              ///< the one the slider and the plot follow
    CatmullRomEnds ends = CatmullRomEnds::Open;
    CatmullRomSpacing spacing = CatmullRomSpacing::Uniform;
    bool bezier = false;                         ///< §2.3: the points as a Bézier control polygon too
    bool controlPoints = true;                   ///< the points q_i, their labels and polygon (Matlab `puntvis`)
    bool catmullRom = true;                      ///< the Catmull-Rom curves of the tensions (off: Fig 2.1 shows the spline alone)
    bool spline = false;                         ///< Def 2.3: the C² cubic spline through the points
    SplineEnds splineEnds = SplineEnds::Natural; ///< its end conditions (cubic_spline.h)
    Rational startSlope{0}, endSlope{0};         ///< s′(x_0) and s′(x_k) of clamped ends
    bool compareEnds = false;                    ///< Ex 2.13: the open and cyclic curves side by side
    bool allTausInPlot = false;                  ///< Ex 2.12: the blending functions of every τ
    bool curvaturePlot = false;                  ///< §2.3: the plot shows κ against arc length instead
    PlaneSplineSettings planeSpline;             ///< the "C² spline in the plane" family (plane_spline_settings.h)
    FunctionDataSettings functionData;           ///< the "function data" family (function_data_settings.h)

    bool operator==(const CatmullRomSettings& o) const;
    bool operator!=(const CatmullRomSettings& o) const { return !(*this == o); }
};

/// T, C, B at point `i` (zeros past the end of settings.tcb).
TcbKnot<Rational> tcbAt(const CatmullRomSettings& settings, std::size_t i);

/// "open", "cyclic", "closed", "segment"; "uniform", "centripetal", "chordal".
QString endsKey(CatmullRomEnds ends);
std::optional<CatmullRomEnds> endsFromKey(const QString& key);
QString spacingKey(CatmullRomSpacing spacing);
std::optional<CatmullRomSpacing> spacingFromKey(const QString& key);
/// α of the spacing: 0, 1/2, 1.
double spacingAlpha(CatmullRomSpacing spacing);

/// Why a typed tension is refused.
enum class TensionProblem { None, NotANumber, OutOfRange };
/// Reads "1/2", "-0.25", "−1/2" (Unicode minus too); nullopt with the problem otherwise.
std::optional<Rational> parseTension(const QString& text, TensionProblem* problem = nullptr);
/// A tension (or an end slope) as its exact text, "1/2" or "-2", as the document writes it.
QString tensionText(const Rational& tau);

/// The settings as JSON (taus as exact texts "1/2") and back. fromJson checks everything
/// (known keys, τ in range, counts) and returns nullopt with `error` set (in English; the
/// tab shows its own translated message) on bad data.
void writeSettings(const CatmullRomSettings& s, QJsonObject& json);
std::optional<CatmullRomSettings> readSettings(const QJsonObject& json, QString* problem);

} // namespace granota::ui
