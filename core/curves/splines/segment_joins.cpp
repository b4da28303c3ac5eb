#include "core/curves/splines/segment_joins.h"

namespace granota {

template std::vector<JoinValues<double>> segmentJoinValues(const std::vector<Vec2<Polynomial<double>>>&, int, bool, double);
template std::vector<JoinValues<Rational>> segmentJoinValues(const std::vector<Vec2<Polynomial<Rational>>>&, int, bool, double);

} // namespace granota
