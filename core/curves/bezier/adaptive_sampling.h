#pragma once
/// \file adaptive_sampling.h
/// Adaptive sampling of a Bézier curve (beyond the thesis, docs/work-precision.md "uniform vs adaptive
/// subdivision"): an interval [a, b] of the parameter is split while the curve's midpoint
/// c((a+b)/2) lies farther than `tolerance` from the chord c(a)c(b). Flat parts get few
/// points and tight bends many, where uniform sampling (the Matlab `part`) spends the same
/// number of points everywhere.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

struct AdaptiveSample {
    std::vector<double> t;     ///< increasing parameters, t[0] = 0, t.back() = 1
    std::vector<Point> points; ///< c(t[i])
};

/// `minDepth` levels are always split (a symmetric curve can have its midpoint on the chord);
/// no interval is split beyond `maxDepth` levels (2^maxDepth intervals at most).
AdaptiveSample sampleBezierAdaptive(const std::vector<Point>& controlPoints, double tolerance, int minDepth = 2,
                                    int maxDepth = 20);

/// The largest distance between the curve and the polyline through its samples at `t`:
/// on each interval [t_i, t_{i+1}] the curve is compared with its chord at `probes` points,
/// evaluated in long double (the reference of the sampling report).
double polylineDeviation(const std::vector<Point>& controlPoints, const std::vector<double>& t, int probes = 16);

} // namespace granota
