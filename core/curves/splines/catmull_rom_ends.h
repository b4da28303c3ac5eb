#pragma once
/// \file catmull_rom_ends.h
/// The end modes a Catmull-Rom comparison offers: Def 2.10's three (as the Matlab
/// `Rep_CatmullRom`) and the single segment of Def 2.8 (only the segments that have both
/// neighbours: with 4 points, the segment from q1 to q2 of Ex 2.11), and the segments of a
/// curve in each of them, exact (Rational) or in doubles.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <vector>

namespace granota {

enum class CatmullRomEnds { Open, Cyclic, Closed, Segment };

/// The core's mode for the ends (Segment uses the open curve's interior segments).
CatmullRomMode coreMode(CatmullRomEnds ends);

/// The mode Ex 2.13 compares with: cyclic for an open curve, open otherwise.
CatmullRomEnds comparedEnds(CatmullRomEnds ends);

/// The index of the first point of segment 0 (1 for Segment mode: the first segment starts at q1).
int firstSegmentStart(CatmullRomEnds ends);

/// The segments of the curve through `q` (Def 2.10; Segment: the open curve's interior
/// segments, Def 2.8). Exact with Rational (uniform spacing only).
Expected<std::vector<Vec2<Polynomial<Rational>>>> exactCurveSegments(const std::vector<RPoint>& q, const Rational& tau,
                                                                     CatmullRomEnds ends);
Expected<std::vector<Vec2<Polynomial<double>>>> curveSegments(const std::vector<Point>& q, double tau, CatmullRomEnds ends,
                                                              double alpha);

} // namespace granota
