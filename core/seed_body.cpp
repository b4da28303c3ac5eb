#include "core/seed_body.h"

#include "core/point_in_polygon.h"

#include <algorithm>
#include <limits>
#include <string>

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
        {p.gravity.x, "gravity x", false},   {p.gravity.y, "gravity y", false},
        {p.friction.x, "friction x", false}, {p.friction.y, "friction y", false},
        {p.v0.x, "v0 x", false},             {p.v0.y, "v0 y", false},
        {p.areaFactor, "area factor", false}, {p.targetArea, "target area", true},
        {p.springLength, "spring length", true}, {p.velmax, "velmax", true},
        {p.center.x, "centre x", false},     {p.center.y, "centre y", false},
        {p.radius, "radius", true},          {p.width, "width", true},
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
            {l.upper, n + " upper length"}, {l.lower, n + " lower length"},
            {l.shoulderMin, n + " shoulder minimum angle"}, {l.shoulderMax, n + " shoulder maximum angle"},
            {l.elbowMin, n + " elbow minimum angle"}, {l.elbowMax, n + " elbow maximum angle"},
        };
        for (std::size_t k = 0; k < 6; ++k)
            if (auto e = checkReal(legFields[k].first, legFields[k].second.c_str(), k < 2))
                return e;
    }
    if (p.sides < 3 || p.sides > kMaxSides)
        return makeError(ErrorCode::OutOfRange, "sides must be between 3 and " + std::to_string(kMaxSides) + ", got "
                                                    + std::to_string(p.sides));
    if (p.width < 1 || p.height < 1)
        return makeError(ErrorCode::OutOfRange, "the frame must be at least 1 x 1 px");
    return std::nullopt;
}

template <class R>
SeedBody<R>::SeedBody(const FrogParams& params, SeedComponents components)
    : m_params(params), m_components(components), m_n(params.sides),
      m_gravity(R(params.gravity.x), R(params.gravity.y)), m_friction(R(params.friction.x), R(params.friction.y)),
      m_areaFactor(R(params.areaFactor)), m_velmax(R(params.velmax)), m_radius(R(params.radius)),
      m_springLength(R(params.springLength)),
      // `width-1` and `height-1` of the sketch (ints there; exact here for integral sizes).
      m_xmax(R(params.width - 1)), m_ymax(R(params.height - 1)),
      m_mouse(R(params.center.x), R(params.center.y))
{
    const auto n1 = std::size_t(m_n) + 1;
    m_vert.resize(n1);
    m_molls.assign(n1, R(0));
    m_estruc.assign(n1, R(0));
    m_corr.resize(n1);
    m_puntA.resize(n1);
    m_puntB.resize(n1);
    m_applied.assign(n1, Vec(R(0), R(0)));
    m_num.resize(n1);
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
    const R pi = R(3.14159265358979323846);
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
    // The rest of Poligon.inicialitza: springs, the frame, the target area.
    for (int i = 0; i < m_n; ++i)
        m_molls[std::size_t(i)] = m_springLength;
    if (m_components.bounds) {
        // "Comprovem que tots els punts estiguen dins la pantalla".
        for (auto& v : m_vert) {
            v.fita(R(0), m_xmax, R(0), m_ymax);
            v.fitaant(R(0), m_xmax, R(0), m_ymax);
        }
    }
    m_areal = R(m_params.targetArea);
    for (auto& c : m_applied)
        c = Vec(R(0), R(0));
}

template <class R> R SeedBody<R>::area() const
{
    // Annex II, calculaarea: trapezoids between each edge and the x axis (§4.5),
    // L = x_i − x_{i+1}, W = (y_i + y_{i+1})/2, summed in this order.
    R area = 0;
    for (int i = 0; i < m_n; ++i) {
        const Vec& a = m_vert[std::size_t(i)].pos;
        const Vec& b = m_vert[std::size_t(i) + 1].pos;
        const R L = a.x - b.x;
        const R W = (a.y + b.y) / R(2);
        area = area + L * W;
    }
    return area;
}

template <class R> void SeedBody<R>::step()
{
    // Annex II, Poligon.actualitza, as SeedFrog.java runs it.
    const int N = m_n;
    const auto n1 = std::size_t(N) + 1;
    const Vec g = m_components.gravity ? m_gravity : Vec(R(0), R(0));
    const Vec zero(R(0), R(0));
    auto& v = m_vert;

    // §4.6: Verlet first, for every vertex including the copy N.
    for (std::size_t i = 0; i < n1; ++i) {
        v[i].verlet(m_friction, g, m_velmax);
        m_corr[i] = zero;
        m_num[i] = 0;
    }

    // §4.4: springs. Each edge i → i+1 proposes targets at distance molls[i]/2 either
    // side of its midpoint: punt_a[i] for vertex i and punt_b[i+1] for vertex i+1.
    if (m_components.springs) {
        for (int i = 0; i < N; ++i) {
            const Vec& p = v[std::size_t(i)].pos;
            const Vec& q = v[std::size_t(i) + 1].pos;
            const Vec mig(R((p.x + q.x) / R(2)), R((p.y + q.y) / R(2)));
            Vec d(R(p.x - q.x), R(p.y - q.y));
            // A zero-length edge: PVector.normalize leaves d = 0 and both targets are the
            // midpoint — finite, so kept as in the seed.
            seedmath::normalize(d);
            const R half = R(m_molls[std::size_t(i)] * R(0.5f));
            m_puntA[std::size_t(i)] = Vec(R(mig.x + half * d.x), R(mig.y + half * d.y));
            m_puntB[std::size_t(i) + 1] = Vec(R(mig.x - half * d.x), R(mig.y - half * d.y));
        }
        m_puntA[std::size_t(N)] = m_puntA[0];
        m_puntB[0] = m_puntB[std::size_t(N)];
        // "Apliquem les correccions 5 voltes": the positions do not change between the
        // passes, so each pass adds the same two corrections again. `punt_a[i] !=
        // vert[i].posicio` compares Java references and is always true: both are added.
        for (std::size_t i = 0; i < n1; ++i) {
            const Vec ca(R(m_puntA[i].x - v[i].pos.x), R(m_puntA[i].y - v[i].pos.y));
            const Vec cb(R(m_puntB[i].x - v[i].pos.x), R(m_puntB[i].y - v[i].pos.y));
            for (int j = 0; j < 5; ++j) {
                m_corr[i] = Vec(R(m_corr[i].x + ca.x), R(m_corr[i].y + ca.y));
                m_corr[i] = Vec(R(m_corr[i].x + cb.x), R(m_corr[i].y + cb.y));
                m_num[i] += 2;
            }
        }
    }

    // §4.6–4.7 (Annex II, "Si esta agafat"): while held, the anchors ({0, 1, N−1, N} in
    // the final program) are pulled to their grab distance estruc from the mouse along
    // the mouse→vertex line.
    const bool held = m_components.grab && m_grabbed;
    if (held) {
        for (int a : m_anchors) {
            const auto i = std::size_t(a);
            Vec d(R(v[i].pos.x - m_mouse.x), R(v[i].pos.y - m_mouse.y));
            seedmath::normalize(d); // mouse on the vertex: d = 0, target = the mouse (finite)
            const Vec c(R(m_mouse.x + m_estruc[i] * d.x), R(m_mouse.y + m_estruc[i] * d.y));
            const Vec correc(R(c.x - v[i].pos.x), R(c.y - v[i].pos.y));
            m_corr[i] = Vec(R(m_corr[i].x + correc.x), R(m_corr[i].y + correc.y));
            m_num[i] += 1;
        }
    }

    // §4.5: area. F = C·(A_target − A)/N pushes every vertex along the normal of the chord
    // between its neighbours, five times. SeedFrog.java (and the reference trace) applies
    // the correction of vertices 0 and N inside the five passes.
    m_aloc = area();
    if (m_components.area) {
        if (m_areal != m_aloc) {
            R F = m_areaFactor * (m_areal - m_aloc) / R(N);
            // Guard: with an accepted but absurd factor (C and the area both near 1e15) the
            // product overflows R, and ∞ times a zero normal component would be NaN; any F
            // beyond this bound is cut by the ±velmax clamp below anyway.
            const R fmax = std::numeric_limits<R>::max() / R(64);
            if (!(F <= fmax)) F = fmax;
            if (!(F >= -fmax)) F = -fmax;
            for (int i = 1; i < N; ++i) {
                const Vec& next = v[std::size_t(i) + 1].pos;
                const Vec& before = v[std::size_t(i) - 1].pos;
                Vec p(R(next.y - before.y), R(-next.x + before.x));
                seedmath::normalize(p); // coincident neighbours: p = 0, no push (finite)
                const Vec fp(R(F * p.x), R(F * p.y));
                for (int j = 0; j < 5; ++j)
                    m_corr[std::size_t(i)] = Vec(R(m_corr[std::size_t(i)].x + fp.x), R(m_corr[std::size_t(i)].y + fp.y));
                m_num[std::size_t(i)] += 5;
            }
            const Vec& next = v[1].pos;
            const Vec& before = v[std::size_t(N) - 1].pos;
            Vec p(R(next.y - before.y), R(-next.x + before.x));
            seedmath::normalize(p);
            const Vec fp(R(F * p.x), R(F * p.y));
            for (int j = 0; j < 5; ++j) {
                m_corr[0] = Vec(R(m_corr[0].x + fp.x), R(m_corr[0].y + fp.y));
                m_corr[std::size_t(N)] = Vec(R(m_corr[std::size_t(N)].x + fp.x), R(m_corr[std::size_t(N)].y + fp.y));
            }
            m_num[0] += 5;
            m_num[std::size_t(N)] += 5;
        }
    }

    // Annex II, "Corregim la posicio de les ancores si estan massa lluny": while held,
    // vertices 1 and N−1 are kept within 10 px of the mouse in x and above it, vertices 0
    // and N inside the frame in x and 10 px above the mouse. These corrections do not
    // count in num_correccions (so they are averaged with the others).
    if (held && m_components.grabMode == GrabMode::Anchors) {
        const R mx = m_mouse.x, my = m_mouse.y;
        for (int a : m_anchors) {
            const auto i = std::size_t(a);
            Vec& c = m_corr[i];
            const Vec& p = v[i].pos;
            if (a > 0 && a < N) {
                if (p.x < R(mx - R(10))) c = Vec(R(c.x + R(mx - R(10)) - p.x), c.y);
                else if (p.x > R(mx + R(10))) c = Vec(R(c.x + R(mx + R(10)) - p.x), c.y);
                if (p.y < 0) c = Vec(c.x, R(c.y - p.y));
                else if (p.y > R(my - R(1))) c = Vec(c.x, R(c.y + R(my - R(1)) - p.y));
            } else {
                if (p.x < 0) c = Vec(R(c.x - p.x), c.y);
                else if (p.x > m_xmax) c = Vec(R(c.x + m_xmax - p.x), c.y);
                if (p.y < 0) c = Vec(c.x, R(c.y - p.y));
                else if (p.y > R(my - R(10))) c = Vec(c.x, R(c.y + R(my - R(10)) - p.y));
            }
        }
    }

    // The average of the corrections of each vertex, clamped per axis to ±velmax.
    for (std::size_t i = 0; i < n1; ++i) {
        if (m_num[i] >= 1) {
            Vec m(R(m_corr[i].x / R(m_num[i])), R(m_corr[i].y / R(m_num[i])));
            if (m.x < -m_velmax) m.x = -m_velmax; else if (m.x > m_velmax) m.x = m_velmax;
            if (m.y < -m_velmax) m.y = -m_velmax; else if (m.y > m_velmax) m.y = m_velmax;
            v[i].pos = Vec(R(v[i].pos.x + m.x), R(v[i].pos.y + m.y));
            m_applied[i] = m;
        } else {
            m_applied[i] = zero;
        }
    }

    // §4.2: the frame. Only the current position is clamped (fita, not fitaant).
    if (m_components.bounds)
        for (auto& vert : v)
            vert.fita(R(0), m_xmax, R(0), m_ymax);
}

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
            if (m_vert[std::size_t(i)].pos.y <= clau.y)
                m_anchors.push_back(i);
        break;
    }
    for (int a : m_anchors) {
        const auto i = std::size_t(a);
        m_estruc[i] = seedmath::dist(m_vert[i].pos.x, m_vert[i].pos.y, clau.x, clau.y);
    }
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
    // (core/point_in_polygon.h): estadins misses every click on the vertical through a
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
        out.emplace_back(double(m_vert[std::size_t(i)].pos.x), double(m_vert[std::size_t(i)].pos.y));
    return out;
}

template <class R> std::vector<Point> SeedBody<R>::previousVertices() const
{
    std::vector<Point> out;
    out.reserve(std::size_t(m_n));
    for (int i = 0; i < m_n; ++i)
        out.emplace_back(double(m_vert[std::size_t(i)].prev.x), double(m_vert[std::size_t(i)].prev.y));
    return out;
}

template class SeedBody<float>;
template class SeedBody<double>;

} // namespace granota
