#include "core/curves/splines/catmull_rom_ends.h"

namespace granota {

namespace {

/// Segment mode: the open curve without its two end segments (those are the ones Def 2.10
/// has to invent neighbours for); with 4 points, the single segment of Def 2.8.
template <class S>
Expected<std::vector<Vec2<Polynomial<S>>>> interiorSegmentsOnly(Expected<std::vector<Vec2<Polynomial<S>>>> open,
                                                                std::size_t count)
{
    if (!open)
        return open;
    if (count < 4)
        return makeError(ErrorCode::TooFewPoints, "A single segment needs 4 points.");
    std::vector<Vec2<Polynomial<S>>> inner(open->begin() + 1, open->end() - 1);
    return inner;
}

} // namespace

CatmullRomMode coreMode(CatmullRomEnds ends)
{
    switch (ends) {
    case CatmullRomEnds::Cyclic: return CatmullRomMode::Cyclic;
    case CatmullRomEnds::Closed: return CatmullRomMode::Closed;
    case CatmullRomEnds::Open:
    case CatmullRomEnds::Segment: return CatmullRomMode::Open;
    }
    return CatmullRomMode::Open;
}

CatmullRomEnds comparedEnds(CatmullRomEnds ends)
{
    return ends == CatmullRomEnds::Open ? CatmullRomEnds::Cyclic : CatmullRomEnds::Open;
}

int firstSegmentStart(CatmullRomEnds ends) { return ends == CatmullRomEnds::Segment ? 1 : 0; }

Expected<std::vector<Vec2<Polynomial<Rational>>>> exactCurveSegments(const std::vector<RPoint>& q, const Rational& tau,
                                                                     CatmullRomEnds ends)
{
    auto segs = catmullRomSegments(q, tau, coreMode(ends));
    if (ends == CatmullRomEnds::Segment)
        return interiorSegmentsOnly(std::move(segs), q.size());
    return segs;
}

Expected<std::vector<Vec2<Polynomial<double>>>> curveSegments(const std::vector<Point>& q, double tau, CatmullRomEnds ends,
                                                              double alpha)
{
    auto segs = catmullRomSegments(q, tau, coreMode(ends), alpha);
    if (ends == CatmullRomEnds::Segment)
        return interiorSegmentsOnly(std::move(segs), q.size());
    return segs;
}

} // namespace granota
