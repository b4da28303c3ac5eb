#pragma once
/// \file parametrization.h
/// The parameters t_0 = 0 ≤ t_1 ≤ … ≤ t_k = 1 at which a fitted Bézier curve should pass
/// near the data points Q_0..Q_k (§2.1.3, the criteria after Nota 2.2):
///  - uniform: t_i = i/k (Ex 2.7, Ex 2.8, Matlab `BezParamEqui`);
///  - chord length: t_i = Σ_{j≤i} d_j / Σ_j d_j with d_j = |Q_j − Q_{j−1}| (Ex 2.9, Ex 2.10,
///    Matlab `BezParamProp`). The thesis's Matlab code uses |Q_j| and Ex 2.9 writes (1 − 7)
///    where Q_3 has x = 8: Granota implements the definition, so Ex 2.9 has d_4 = 7√2;
///  - centripetal (beyond the thesis): the same with √d_j;
///  - Annex III (the thesis's own Matlab `BezParamProp`, as it computes): d_j = |Q_{j−1}|,
///    the distance of the point before from the origin, not from its neighbour, so
///    t_i = Σ_{j<i} |Q_j| / Σ_{j<k} |Q_j|. Figs 2.7/2.8 were drawn with it (Ex 2.9:
///    t = 0, 0, 0.19913, 0.48074, 1); docs/thesis-errata.md.

#include "core/exact/radical_sum.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granota {

enum class Parametrization {
    Uniform,     ///< t_i = i/k
    ChordLength, ///< proportional to the distances between consecutive points
    Centripetal, ///< proportional to the square roots of those distances
    AnnexIII,    ///< as Annex III's BezParamProp computes them: proportional to |Q_{i−1}|
};

/// "uniform", "chord", "centripetal", "annex-iii" (case-insensitive); nullopt for anything else.
std::optional<Parametrization> parseParametrization(std::string_view text);
/// The name parseParametrization() reads back.
std::string toString(Parametrization p);

/// The parameters t_0..t_k for the points q (k + 1 = q.size(); empty for no points, {0}
/// for one). t_0 = 0 and t_k = 1 exactly, and the t_i never decrease; coincident
/// consecutive points give equal parameters. When the total length is zero (all points
/// coincide) or not finite, chord length and centripetal fall back to uniform and set
/// *fellBackToUniform (when given) to true; otherwise it is set to false.
std::vector<double> parameters(const std::vector<Point>& q, Parametrization p, bool* fellBackToUniform = nullptr);

/// The same parameters exactly. Uniform always exists; chord length only when every
/// distance d_j is rational (the squared distance is the square of a rational, see
/// exactSqrt), centripetal only when every √d_j is rational; nullopt otherwise. Falls
/// back to uniform, as above, when all the points coincide.
std::optional<std::vector<Rational>> exactParameters(const std::vector<RPoint>& q, Parametrization p,
                                                     bool* fellBackToUniform = nullptr);

/// Chord-length and Annex III parameters in radicals, t_i = S_i / S_k with S_i the sum of
/// the first i distances, each in simplest radical form (square_root.h), rationalised when
/// radical_sum.h can (Ex 2.9: t_1 = (11√5 − 10)/101). nullopt for uniform and centripetal
/// parameters (uniform ones are exactParameters'; centripetal ones are fourth roots), for
/// fewer than 2 or more than kMaxRadicalPoints points, when a distance is too large to
/// simplify, and when all the points coincide.
std::optional<std::vector<RadicalQuotient>> radicalParameters(const std::vector<RPoint>& q, Parametrization p);

} // namespace granota
