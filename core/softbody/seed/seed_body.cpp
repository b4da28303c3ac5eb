#include "core/softbody/seed/seed_body.h"
#include "core/base/math_constants.h"

#include "core/softbody/polygon_geometry.h"
#include "core/softbody/seed/seed_lanes.h"
#include "core/softbody/seed/seed_leg_lanes.h"

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>

namespace granota {

namespace {

constexpr double kMaxMagnitude = 1e15;
constexpr int kMaxSides = 10000;

std::optional<Error> checkReal(double v, const char* name, bool nonNegative)
{
    if (!std::isfinite(v))
        return makeError(ErrorCode::InvalidInput, std::string(name) + " must be a finite number");
    if (std::abs(v) > kMaxMagnitude)
        return makeError(ErrorCode::OutOfRange, std::string(name) + " must be at most 1e15 in magnitude");
    if (nonNegative && v < 0)
        return makeError(ErrorCode::OutOfRange, std::string(name) + " must not be negative");
    return std::nullopt;
}

} // namespace

std::optional<Error> checkSeedParams(const FrogParams& p)
{
    struct Field {
        double value;
        const char* name;
        bool nonNegative;
    };
    const Field fields[] = {
        {p.gravity.x, "gravity x", false},
        {p.gravity.y, "gravity y", false},
        {p.friction.x, "friction x", false},
        {p.friction.y, "friction y", false},
        {p.v0.x, "v0 x", false},
        {p.v0.y, "v0 y", false},
        {p.areaFactor, "area factor", false},
        {p.targetArea, "target area", true},
        {p.springLength, "spring length", true},
        {p.velmax, "velmax", true},
        {p.center.x, "centre x", false},
        {p.center.y, "centre y", false},
        {p.radius, "radius", true},
        {p.width, "width", true},
        {p.height, "height", true},
    };
    for (const Field& f : fields)
        if (auto e = checkReal(f.value, f.name, f.nonNegative))
            return e;
    static const char* const legNames[4] = {"front right leg", "front left leg", "back right leg", "back left leg"};
    for (int i = 0; i < 4; ++i) {
        const LegParams& l = p.legs[std::size_t(i)];
        const std::string n = legNames[i];
        const std::pair<double, std::string> legFields[] = {
            {l.upper, n + " upper length"},
            {l.lower, n + " lower length"},
            {l.shoulderMin, n + " shoulder minimum angle"},
            {l.shoulderMax, n + " shoulder maximum angle"},
            {l.elbowMin, n + " elbow minimum angle"},
            {l.elbowMax, n + " elbow maximum angle"},
        };
        for (std::size_t k = 0; k < 6; ++k)
            if (auto e = checkReal(legFields[k].first, legFields[k].second.c_str(), k < 2))
                return e;
    }
    if (p.sides < 3 || p.sides > kMaxSides)
        return makeError(ErrorCode::OutOfRange,
                         "sides must be between 3 and " + std::to_string(kMaxSides) + ", got " + std::to_string(p.sides));
    if (p.width < 1 || p.height < 1)
        return makeError(ErrorCode::OutOfRange, "the frame must be at least 1 x 1 px");
    return std::nullopt;
}

template <class R>
SeedBody<R>::SeedBody(const FrogParams& params, SeedComponents components)
    : m_params(params), m_components(components), m_n(params.sides), m_gravity(R(params.gravity.x), R(params.gravity.y)),
      m_friction(R(params.friction.x), R(params.friction.y)), m_areaFactor(R(params.areaFactor)), m_velmax(R(params.velmax)),
      m_radius(R(params.radius)), m_springLength(R(params.springLength)),
      // `width-1` and `height-1` of the sketch (ints there; exact here for integral sizes).
      m_xmax(R(params.width - 1)), m_ymax(R(params.height - 1)), m_mouse(R(params.center.x), R(params.center.y))
{
    const auto n1 = std::size_t(m_n) + 1;
    m_vert.resize(n1);
    m_estruc.assign(n1, R(0));
    m_applied.assign(n1, Vec(R(0), R(0)));
    // Each array holds the N + 1 vertices rounded up to whole packs of lanes, plus one more
    // pack: the edge loops read the pack after each. The spare lanes start as zeros,
    // compute garbage that stays finite (it is clamped like the vertices) and are never
    // read back.
    const auto lanesPerPack = std::size_t(8); // room for packs of four or of eight lanes
    m_stride = (n1 + lanesPerPack - 1) / lanesPerPack * lanesPerPack + lanesPerPack;
    m_lanes.assign(m_stride * LaneArrayCount, R(0));
}

template <class R> Expected<SeedBody<R>> SeedBody<R>::create(const FrogParams& params, SeedComponents components)
{
    if (auto e = checkSeedParams(params))
        return *e;
    SeedBody body(params, components);
    // SeedFrog.java, main → Granota → cos.inicialitza(centre, v0).
    body.initialise(Vec(R(params.center.x), R(params.center.y)), Vec(R(params.v0.x), R(params.v0.y)));
    return body;
}

template <class R>
Expected<SeedBody<R>> SeedBody<R>::createFromShape(const FrogParams& params, const std::vector<Point>& shape,
                                                   SeedComponents components)
{
    if (shape.size() < 3 || shape.size() > 10000)
        return makeError(ErrorCode::OutOfRange, "a body needs 3 to 10000 vertices");
    for (const Point& p : shape)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return makeError(ErrorCode::InvalidInput, "the body's shape has a non-finite point");
    FrogParams p = params;
    p.sides = static_cast<int>(shape.size());
    if (auto e = checkSeedParams(p))
        return *e;
    SeedBody body(p, components);
    body.m_shape = shape;
    body.initialise(Vec(R(p.center.x), R(p.center.y)), Vec(R(p.v0.x), R(p.v0.y)));
    return body;
}

template <class R> void SeedBody<R>::initialise(const Vec& centre, const Vec& vIni)
{
    // Annex II, Poligon.inicialitza. PI, HALF_PI and TWO_PI are Processing's float
    // constants (HALF_PI = PI/2 and TWO_PI = 2·PI exactly).
    const R pi = R(kPi);
    const R halfPi = pi / R(2), twoPi = R(2) * pi;
    const int N = m_n;
    m_grabbed = false;
    const R x = centre.x, y = centre.y;
    if (!m_shape.empty()) {
        // A given rest shape (§4.9's Bézier points, §5.2.3's shapes), translated to the centre.
        for (int i = 0; i <= N; ++i) {
            const Point& o = m_shape[std::size_t(i % N)];
            SeedVertex<R>& v = m_vert[std::size_t(i)];
            v.pos = Vec(R(x + R(o.x)), R(y + R(o.y)));
            v.prev = Vec(R(v.pos.x - vIni.x), R(v.pos.y - vIni.y));
        }
        finishInitialise();
        return;
    }
    // The seed's r is an int (abs(height/6)); an integral FrogParams::radius gives the same
    // value, a fractional one is kept as it is.
    const R r = m_radius;
    R ang = -halfPi;
    // §4.1: the vertices go round from the top (clockwise on screen, y down); the previous
    // position is set back by v_ini so that the first Verlet step moves by v_ini.
    for (int i = 0; i < N; ++i) {
        const R c = seedmath::cos(ang), s = seedmath::sin(ang);
        SeedVertex<R>& v = m_vert[std::size_t(i)];
        v.prev = Vec(R(x + r * c - vIni.x), R(y + r * s - vIni.y));
        v.pos = Vec(R(x + r * c), R(y + r * s));
        ang = ang + twoPi / R(N);
    }
    {
        const R c = seedmath::cos(R(-halfPi)), s = seedmath::sin(R(-halfPi));
        SeedVertex<R>& v = m_vert[std::size_t(N)];
        v.prev = Vec(R(x + r * c - vIni.x), R(y + r * s - vIni.y));
        v.pos = Vec(R(x + r * c), R(y + r * s));
    }
    finishInitialise();
}

template <class R> void SeedBody<R>::finishInitialise()
{
    // The rest of Poligon.inicialitza: springs (molls[i] = the spring length for every
    // edge, kept as m_springLength), the frame, the target area.
    if (m_components.bounds) {
        // "Comprovem que tots els punts estiguen dins la pantalla".
        for (auto& v : m_vert) {
            v.fita(R(0), m_xmax, R(0), m_ymax);
            v.fitaant(R(0), m_xmax, R(0), m_ymax);
        }
    }
    m_areal = R(m_params.targetArea);
    // The vertices go into the lane arrays, where the steps keep them.
    R* const x = lanes(X);
    R* const y = lanes(Y);
    R* const px = lanes(PrevX);
    R* const py = lanes(PrevY);
    for (std::size_t i = 0; i < m_vert.size(); ++i) {
        x[i] = m_vert[i].pos.x, y[i] = m_vert[i].pos.y;
        px[i] = m_vert[i].prev.x, py[i] = m_vert[i].prev.y;
    }
    m_vertStale = false;
    std::fill(lanes(AppliedX), lanes(AppliedX) + m_stride, R(0));
    std::fill(lanes(AppliedY), lanes(AppliedY) + m_stride, R(0));
}

template <class R> void SeedBody<R>::syncVertices() const
{
    const R* const x = lanes(X);
    const R* const y = lanes(Y);
    const R* const px = lanes(PrevX);
    const R* const py = lanes(PrevY);
    for (std::size_t i = 0; i < m_vert.size(); ++i) {
        m_vert[i].pos = Vec(x[i], y[i]);
        m_vert[i].prev = Vec(px[i], py[i]);
    }
    m_vertStale = false;
}

template <class R> const std::vector<typename SeedBody<R>::Vec>& SeedBody<R>::corrections() const
{
    // Gathered only when asked (the readouts), not in every step.
    const R* ax = lanes(AppliedX);
    const R* ay = lanes(AppliedY);
    for (std::size_t i = 0; i < m_applied.size(); ++i)
        m_applied[i] = Vec(ax[i], ay[i]);
    return m_applied;
}

template <class R> R SeedBody<R>::area() const
{
    // Annex II, calculaarea: trapezoids between each edge and the x axis (§4.5),
    // L = x_i − x_{i+1}, W = (y_i + y_{i+1})/2, summed in this order. Not trapezoidArea
    // (polygon_geometry.h), which halves once at the end: the seed halves every term, in
    // its float lanes, as the thesis's program does, so that its traces are reproduced.
    const R* const x = lanes(X);
    const R* const y = lanes(Y);
    R area = 0;
    for (int i = 0; i < m_n; ++i) {
        const R L = x[i] - x[i + 1];
        const R W = (y[i] + y[i + 1]) / R(2);
        area = area + L * W;
    }
    return area;
}

template <class R> void SeedBody<R>::step()
{
    // A body of up to 12 vertices (the frog has 11) takes a step whose loops have a fixed
    // number of packs, unrolled by the compiler; the operations are the same.
    NothingAlong nothing;
    stepWith(nothing);
}

template <class R> template <class Along> void SeedBody<R>::stepWith(Along& along)
{
#ifdef GRANOTA_SEED_AVX2
    if constexpr (std::is_same<R, float>::value) {
        // Up to 15 vertices (the frog has 11) in one or two packs of eight.
        if (m_n < 16 && seedWideLanes()) {
            if (m_n < 8)
                stepPacksWide<1>(along);
            else
                stepPacksWide<2>(along);
            return;
        }
    }
#endif
    switch ((m_n + kSeedLanes) / kSeedLanes) {
    case 1: stepPacks<1>(along); break;
    case 2: stepPacks<2>(along); break;
    case 3: stepPacks<3>(along); break;
    default: stepPacks<0>(along); break;
    }
}

#define GRANOTA_STEP_NAME stepPacks
#define GRANOTA_STEP_LANES Lanes<R>
#define GRANOTA_STEP_TARGET
#include "core/softbody/seed/seed_body_step.inc"
#undef GRANOTA_STEP_NAME
#undef GRANOTA_STEP_LANES
#undef GRANOTA_STEP_TARGET

#ifdef GRANOTA_SEED_AVX2
#define GRANOTA_STEP_NAME stepPacksWide
#define GRANOTA_STEP_LANES Lanes8<R>
#define GRANOTA_STEP_TARGET GRANOTA_AVX2_TARGET
#include "core/softbody/seed/seed_body_step.inc"
#undef GRANOTA_STEP_NAME
#undef GRANOTA_STEP_LANES
#undef GRANOTA_STEP_TARGET
#endif

template <class R> void SeedBody<R>::holdAt(const Vec& clau)
{
    // Annex II, Poligon.mantindreagafat: the anchors and their distances to the mouse.
    m_grabbed = true;
    m_anchors.clear();
    switch (m_components.grabMode) {
    case GrabMode::Anchors: m_anchors = {0, 1, m_n - 1, m_n}; break;
    case GrabMode::All: // §4.6: a spring from the mouse to every vertex
        for (int i = 0; i <= m_n; ++i)
            m_anchors.push_back(i);
        break;
    case GrabMode::Above: // §4.7: the vertices above the grab point (y smaller on screen)
        for (int i = 0; i <= m_n; ++i)
            if (lanes(Y)[i] <= clau.y)
                m_anchors.push_back(i);
        break;
    }
    for (int a : m_anchors)
        m_estruc[std::size_t(a)] = seedmath::dist(lanes(X)[a], lanes(Y)[a], clau.x, clau.y);
}

template <class R> typename SeedBody<R>::Vec SeedBody<R>::clampMouse(const Point& p) const
{
    // Guard: Processing's mouseX/mouseY come from the window. A point outside it (a drag
    // past the edge, a respawn requested off-screen) is moved to the nearest point of the
    // frame, so that the anchors pull towards a place the body can reach and a respawn
    // never builds a polygon squashed flat against a wall. Non-finite coordinates keep the
    // previous mouse position.
    Vec m = m_mouse;
    if (std::isfinite(p.x))
        m.x = R(std::min(std::max(p.x, 0.0), double(m_xmax)));
    if (std::isfinite(p.y))
        m.y = R(std::min(std::max(p.y, 0.0), double(m_ymax)));
    return m;
}

template <class R> bool SeedBody<R>::press(const Point& mouse)
{
    m_mouse = clampMouse(mouse);
    // mousePressed: `if (!ocupat) if (estadins(mouseX, mouseY))`. The inside test is the
    // crossing test of §4.6 with the vertex double-count of estadins fixed
    // (core/softbody/polygon_geometry.h): estadins misses every click on the vertical through a
    // vertex — the centre of the initial body among them.
    if (!m_components.grab || m_grabbed)
        return false;
    if (!pointInPolygon(Point(double(m_mouse.x), double(m_mouse.y)), vertices()))
        return false;
    holdAt(m_mouse);
    return true;
}

template <class R> void SeedBody<R>::move(const Point& mouse) { m_mouse = clampMouse(mouse); }

template <class R> void SeedBody<R>::release() { m_grabbed = false; }

template <class R> bool SeedBody<R>::respawn(const Point& centre)
{
    // keyPressed(' '): `if (!ocupat)`, inicialitza(mouse, (0, 0)), then hold it.
    if (m_grabbed)
        return false;
    m_mouse = clampMouse(centre);
    initialise(m_mouse, Vec(R(0), R(0)));
    if (m_components.grab)
        holdAt(m_mouse);
    return true;
}

template <class R> void SeedBody<R>::releaseSpawn() { m_grabbed = false; }

template <class R> std::vector<Point> SeedBody<R>::vertices() const
{
    std::vector<Point> out;
    out.reserve(std::size_t(m_n));
    for (int i = 0; i < m_n; ++i)
        out.emplace_back(double(lanes(X)[i]), double(lanes(Y)[i]));
    return out;
}

template <class R> std::vector<Point> SeedBody<R>::previousVertices() const
{
    std::vector<Point> out;
    out.reserve(std::size_t(m_n));
    for (int i = 0; i < m_n; ++i)
        out.emplace_back(double(lanes(PrevX)[i]), double(lanes(PrevY)[i]));
    return out;
}

template class SeedBody<float>;
template class SeedBody<double>;
template void SeedBody<float>::stepWith(SeedLegLanes<float>::Step&);
template void SeedBody<double>::stepWith(SeedLegLanes<double>::Step&);

} // namespace granota
