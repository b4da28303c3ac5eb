#include "core/softbody/seed/stage_body.h"

#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {
bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }
} // namespace

Expected<void> validateFrogParams(const FrogParams& p)
{
    if (p.sides < 3)
        return makeError(ErrorCode::OutOfRange, "sides must be at least 3 (a polygon), got " + std::to_string(p.sides),
                         MessageId::SidesTooFew, {numberArg(p.sides)});
    if (p.sides > 10000)
        return makeError(ErrorCode::OutOfRange, "sides must be at most 10000, got " + std::to_string(p.sides),
                         MessageId::SidesTooMany, {numberArg(p.sides), numberArg(10000)});
    if (!(p.width >= 1) || !(p.height >= 1) || !std::isfinite(p.width) || !std::isfinite(p.height))
        return makeError(ErrorCode::OutOfRange, "the frame must be at least 1 × 1 px", MessageId::FrameTooSmall, {});
    if (!(p.radius >= 0) || !std::isfinite(p.radius))
        return makeError(ErrorCode::OutOfRange, "radius must be a finite number ≥ 0", MessageId::ParameterNotFinite,
                         {textArg("radius"), textArg("≥ 0")});
    if (!(p.targetArea >= 0) || !std::isfinite(p.targetArea))
        return makeError(ErrorCode::OutOfRange, "target_area must be a finite number ≥ 0", MessageId::ParameterNotFinite,
                         {textArg("target_area"), textArg("≥ 0")});
    if (!(p.springLength >= 0) || !std::isfinite(p.springLength))
        return makeError(ErrorCode::OutOfRange, "spring_length must be a finite number ≥ 0", MessageId::ParameterNotFinite,
                         {textArg("spring_length"), textArg("≥ 0")});
    if (!(p.velmax >= 0) || !std::isfinite(p.velmax))
        return makeError(ErrorCode::OutOfRange, "velmax must be a finite number ≥ 0", MessageId::ParameterNotFinite,
                         {textArg("velmax"), textArg("≥ 0")});
    if (!std::isfinite(p.areaFactor))
        return makeError(ErrorCode::InvalidInput, "area_factor must be a finite number", MessageId::ParameterNotFinite,
                         {textArg("area_factor"), textArg("")});
    for (Point q : {p.gravity, p.friction, p.v0, p.center})
        if (!finite(q))
            return makeError(ErrorCode::InvalidInput, "gravity, friction, v0 and center must be finite");
    for (const LegParams& l : p.legs)
        if (!(l.upper >= 0) || !(l.lower >= 0) || !std::isfinite(l.upper) || !std::isfinite(l.lower) ||
            !std::isfinite(l.shoulderMin + l.shoulderMax + l.elbowMin + l.elbowMax))
            return makeError(ErrorCode::OutOfRange, "leg lengths must be finite and ≥ 0, angle limits finite");
    return {};
}

Expected<StageBody> StageBody::create(const FrogParams& params, StageComponents components)
{
    auto valid = validateFrogParams(params);
    if (!valid)
        return valid.error();
    StageBody body(params, components);
    body.build(params.center, params.radius, params.v0);
    return body;
}

void StageBody::build(Point centre, double radius, Point velocity)
{
    m_centre = centre;
    m_radius = radius;
    m_x = regularPolygon(centre, radius, m_p.sides);
    m_v.assign(m_x.size(), velocity);
    m_correction.assign(m_x.size(), Point());
    m_count.assign(m_x.size(), 0);
    if (m_c.bounds)
        for (Point& x : m_x) {
            x.x = std::clamp(x.x, 0.0, m_p.width - 1);
            x.y = std::clamp(x.y, 0.0, m_p.height - 1);
        }
}

void StageBody::followMouse(Point mouse)
{
    if (!finite(mouse))
        return;
    // §4.1: r = |mouseY − h/2|, capped so that a pointer far outside the window cannot make
    // a polygon of astronomical size.
    const double r = std::min(std::fabs(mouse.y - m_p.height / 2), 10 * std::max(m_p.width, m_p.height));
    build(m_centre, r, Point());
}

void StageBody::respawn(Point centre)
{
    if (!finite(centre))
        return;
    if (m_c.bounds) {
        centre.x = std::clamp(centre.x, 0.0, m_p.width - 1);
        centre.y = std::clamp(centre.y, 0.0, m_p.height - 1);
    }
    build(centre, m_p.radius, m_p.v0);
}

void StageBody::step()
{
    const std::size_t n = m_x.size();
    const double xmax = m_p.width - 1, ymax = m_p.height - 1;
    // §4.2: the MRUA update.
    for (std::size_t i = 0; i < n; ++i) {
        if (m_c.gravity)
            m_v[i] += m_p.gravity;
        // Annex II's velmax bounds how far a vertex moves in one step; it keeps a huge
        // gravity or a stiff correction from throwing a vertex to infinity.
        m_v[i].x = std::clamp(m_v[i].x, -m_p.velmax, m_p.velmax);
        m_v[i].y = std::clamp(m_v[i].y, -m_p.velmax, m_p.velmax);
        m_x[i] += m_v[i];
    }
    if (m_c.bounds) {
        for (std::size_t i = 0; i < n; ++i) {
            Point& x = m_x[i];
            Point& v = m_v[i];
            if (m_c.bounce) { // §4.3: back on the edge, velocity reversed and damped by f
                if (x.x < 0 || x.x > xmax) {
                    x.x = std::clamp(x.x, 0.0, xmax);
                    v.x = -m_p.friction.x * v.x;
                }
                if (x.y < 0 || x.y > ymax) {
                    x.y = std::clamp(x.y, 0.0, ymax);
                    v.y = -m_p.friction.y * v.y;
                }
            } else { // §4.2: min/max keep the body in the frame; it stops at the edge
                if (x.x < 0 || x.x > xmax) {
                    x.x = std::clamp(x.x, 0.0, xmax);
                    v.x = 0;
                }
                if (x.y < 0 || x.y > ymax) {
                    x.y = std::clamp(x.y, 0.0, ymax);
                    v.y = 0;
                }
            }
        }
    }
    if (!m_c.springs && !m_c.area)
        return;
    std::fill(m_correction.begin(), m_correction.end(), Point());
    std::fill(m_count.begin(), m_count.end(), 0);
    if (m_c.springs) {
        // §4.4 / Annex II: each edge's two ends should sit molls/2 either side of its
        // midpoint, along the edge; the difference is a correction for both ends.
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            const Point mid(0.5 * (m_x[i].x + m_x[j].x), 0.5 * (m_x[i].y + m_x[j].y));
            Point d = m_x[i] - m_x[j];
            const double len = norm(d);
            if (len > 0)
                d = Point(d.x / len, d.y / len);
            const double half = 0.5 * m_p.springLength;
            m_correction[i] += Point(mid.x + half * d.x, mid.y + half * d.y) - m_x[i];
            m_correction[j] += Point(mid.x - half * d.x, mid.y - half * d.y) - m_x[j];
            ++m_count[i];
            ++m_count[j];
        }
    }
    if (m_c.area) {
        // §4.5: F = C (A_target − A) / N along the normal of the chord v_{i−1} v_{i+1}.
        const double F = m_p.areaFactor * (m_p.targetArea - trapezoidArea(m_x)) / static_cast<double>(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Point& prev = m_x[(i + n - 1) % n];
            const Point& next = m_x[(i + 1) % n];
            Point normal(next.y - prev.y, prev.x - next.x);
            const double len = norm(normal);
            if (len > 0)
                normal = Point(normal.x / len, normal.y / len);
            m_correction[i] += Point(F * normal.x, F * normal.y);
            ++m_count[i];
        }
    }
    for (std::size_t i = 0; i < n; ++i)
        if (m_count[i] > 0 && std::isfinite(m_correction[i].x) && std::isfinite(m_correction[i].y)) {
            // As a velocity: the spring pulls over the following steps (§4.4).
            m_v[i].x += std::clamp(m_correction[i].x / m_count[i], -m_p.velmax, m_p.velmax);
            m_v[i].y += std::clamp(m_correction[i].y / m_count[i], -m_p.velmax, m_p.velmax);
        }
}

} // namespace granota
