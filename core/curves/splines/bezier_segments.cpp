#include "core/curves/splines/bezier_segments.h"

namespace granota {

template std::vector<BezierSegment<double>> bezierSegments(const std::vector<Vec2<Polynomial<double>>>&);
template std::vector<BezierSegment<Rational>> bezierSegments(const std::vector<Vec2<Polynomial<Rational>>>&);

} // namespace granota
