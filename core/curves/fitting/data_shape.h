#pragma once
/// \file data_shape.h
/// What a set of data points Q_0..Q_k looks like before fitting it (§2.1.3), so that the
/// fitting tab can explain degenerate input instead of silently drawing something odd:
/// coincident consecutive points (a zero chord length d_i, so t_{i−1} = t_i), all points
/// coinciding (chord-length parameters undefined), all points on one line.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

struct DataShape {
    bool allCoincide = false; ///< every Q_i is the same point (or there are fewer than 2)
    bool collinear = false;   ///< every Q_i lies on one line (true when they all coincide)
    int zeroChords = 0;       ///< how many consecutive pairs coincide (d_i = 0)
    int firstZeroChord = -1;  ///< the smallest i ≥ 1 with Q_{i−1} = Q_i, or −1
};

/// Collinearity is decided relative to the size of the data: every point within
/// `relativeTolerance` × (largest extent) of the line through the two points farthest
/// apart along the principal direction. Non-finite points are ignored.
DataShape analyseDataShape(const std::vector<Point>& q, double relativeTolerance = 1e-12);

} // namespace granota
