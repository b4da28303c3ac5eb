#include "core/seed_body.h"

#include "core/point_in_polygon.h"
#include "core/seed_lanes.h"
#include "core/seed_leg_lanes.h"

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
    m_estruc.assign(n1, R(0));
    m_applied.assign(n1, Vec(R(0), R(0)));
    // Each array holds the N + 1 vertices rounded up to whole packs of lanes, plus one more
    // pack: the edge loops read the pack after each. The spare lanes start as zeros,
    // compute garbage that stays finite (it is clamped like the vertices) and are never
    // read back.
    const auto lanesPerPack = std::size_t(kSeedLanes);
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
    // L = x_i − x_{i+1}, W = (y_i + y_{i+1})/2, summed in this order.
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
    switch ((m_n + kSeedLanes) / kSeedLanes) {
    case 1: stepPacks<1>(along); break;
    case 2: stepPacks<2>(along); break;
    case 3: stepPacks<3>(along); break;
    default: stepPacks<0>(along); break;
    }
}

template <class R> template <int Packs, class Along> void SeedBody<R>::stepPacks(Along& along)
{
    // Annex II, Poligon.actualitza, as SeedFrog.java runs it. The same operations in the
    // same order on every vertex, four vertices at a time (core/seed_lanes.h); what the
    // seed does several times over is still done as often (the five passes change the
    // rounding), but nothing is allocated and every length is computed once. The vertices
    // stay in the lane arrays from one step to the next. Every array is read and written
    // in whole packs at multiples of four; a neighbour (vertex i ± 1) is shifted in from
    // the next or previous pack in registers (nextLanes, previousLanes).
    using L = Lanes<R>;
    const int N = m_n;
    const int n1 = N + 1;
    const int end = Packs > 0 ? Packs * kSeedLanes : n1; // the packs cover vertices 0 … N
    // The arrays do not overlap: told so (__restrict), the compiler keeps in registers what
    // one pass stored and the next reads.
    R* __restrict const x = lanes(X);
    R* __restrict const y = lanes(Y);
    R* __restrict const px = lanes(PrevX);
    R* __restrict const py = lanes(PrevY);
    R* __restrict const cx = lanes(CorrX);
    R* __restrict const cy = lanes(CorrY);
    R* __restrict const ax = lanes(PuntAX);
    R* __restrict const ay = lanes(PuntAY);
    R* __restrict const bx = lanes(PuntBX);
    R* __restrict const by = lanes(PuntBY);
    const L zero = L::splat(R(0)), half = L::splat(R(0.5f)), vmax = L::splat(m_velmax);
    // The lanes of vertex N, the seed's copy of vertex 0, in the pack starting at i.
    const L lanePos = L::set(R(0), R(1), R(2), R(3)), lastVertex = L::splat(R(N));
    const auto isLast = [&](int i) { return eq(lanePos + L::splat(R(i)), lastVertex); };
    // Whether the pack starting at i holds vertex N: one pack does, so the lanes of the
    // others need no mask (a branch the processor predicts instead of a select per lane).
    const auto holdsLast = [N](int i) { return i <= N && N < i + kSeedLanes; };
    m_vertStale = true;

    // The other computation's parts go in before each part of this step (SeedBody::stepWith).
    along.run(0);
    // §4.6: Verlet first, for every vertex including the copy N (SeedVertex::verlet):
    // x' = x + f∘(x − x_prev) + g, clamped to x ± velmax.
    {
        const Vec g = m_components.gravity ? m_gravity : Vec(R(0), R(0));
        const L fx = L::splat(m_friction.x), fy = L::splat(m_friction.y), gx = L::splat(g.x), gy = L::splat(g.y);
        for (int i = 0; i < end; i += kSeedLanes) {
            const L x0 = L::load(x + i), y0 = L::load(y + i);
            const L nx = x0 + fx * (x0 - L::load(px + i)) + gx;
            const L ny = y0 + fy * (y0 - L::load(py + i)) + gy;
            x0.store(px + i);
            y0.store(py + i);
            clampLanes(nx, x0 - vmax, x0 + vmax).store(x + i);
            clampLanes(ny, y0 - vmax, y0 + vmax).store(y + i);
        }
    }

    // Every vertex gets the same number of corrections (num_correccions) but for the
    // grab's anchors: counted here rather than summed in floats (small integers, exact).
    int numAll = 0;

    along.run(1);
    // §4.4: springs. Each edge i → i+1 proposes targets at distance molls[i]/2 either
    // side of its midpoint: punt_a[i] for vertex i and punt_b[i+1] for vertex i+1 (kept
    // at index i, by edge).
    if (m_components.springs) {
        // molls[i]·0.5f, the same for every edge.
        const L halfSpring = L::splat(R(m_springLength * R(0.5f)));
        for (int i = 0; i < end && i < N; i += kSeedLanes) {
            const L pxl = L::load(x + i), pyl = L::load(y + i);
            const L qx = nextLanes(pxl, L::load(x + i + kSeedLanes)), qy = nextLanes(pyl, L::load(y + i + kSeedLanes));
            // (p + q)/2: halving is exact, so ·0.5 gives the very same bits as /2.
            const L migx = (pxl + qx) * half, migy = (pyl + qy) * half;
            L dx = pxl - qx, dy = pyl - qy;
            // A zero-length edge: PVector.normalize leaves d = 0 and both targets are the
            // midpoint — finite, so kept as in the seed.
            normalizeLanes(dx, dy, sqrt(dx * dx + dy * dy));
            (migx + halfSpring * dx).store(ax + i);
            (migy + halfSpring * dy).store(ay + i);
            (migx - halfSpring * dx).store(bx + i);
            (migy - halfSpring * dy).store(by + i);
        }
        along.run(2);
        // "Apliquem les correccions 5 voltes": the positions do not change between the
        // passes, so each pass adds the same two corrections again (rounded each time, so
        // the five passes stay five). `punt_a[i] != vert[i].posicio` compares Java
        // references and is always true: both are added. Vertex N takes punt_a[0] and
        // vertex 0 punt_b[N], the target of edge N − 1 (the seed's copies of each other).
        L pbx = L::splat(bx[N - 1]), pby = L::splat(by[N - 1]); // the pack before: edge N − 1 last
        for (int i = 0; i < end; i += kSeedLanes) {
            const L x0 = L::load(x + i), y0 = L::load(y + i);
            L tax = L::load(ax + i), tay = L::load(ay + i);
            if (holdsLast(i)) {
                const auto last = isLast(i);
                tax = select(last, L::splat(ax[0]), tax);
                tay = select(last, L::splat(ay[0]), tay);
            }
            const L ebx = L::load(bx + i), eby = L::load(by + i);
            const L tbx = previousLanes(pbx, ebx), tby = previousLanes(pby, eby);
            pbx = ebx, pby = eby;
            const L cax = tax - x0, cay = tay - y0;
            const L cbx = tbx - x0, cby = tby - y0;
            L sx = zero, sy = zero;
            for (int j = 0; j < 5; ++j) {
                sx = sx + cax, sy = sy + cay;
                sx = sx + cbx, sy = sy + cby;
            }
            sx.store(cx + i);
            sy.store(cy + i);
        }
        numAll = 10;
    } else {
        along.run(2);
        for (int i = 0; i < end; i += kSeedLanes) {
            zero.store(cx + i);
            zero.store(cy + i);
        }
    }

    // §4.6–4.7 (Annex II, "Si esta agafat"): while held, the anchors ({0, 1, N−1, N} in
    // the final program) are pulled to their grab distance estruc from the mouse along
    // the mouse→vertex line; each counts one correction more (below).
    const bool held = m_components.grab && m_grabbed;
    if (held) {
        for (int a : m_anchors) {
            Vec d(R(x[a] - m_mouse.x), R(y[a] - m_mouse.y));
            seedmath::normalize(d); // mouse on the vertex: d = 0, target = the mouse (finite)
            const R e = m_estruc[std::size_t(a)];
            const Vec c(R(m_mouse.x + e * d.x), R(m_mouse.y + e * d.y));
            cx[a] = R(cx[a] + R(c.x - x[a]));
            cy[a] = R(cy[a] + R(c.y - y[a]));
        }
    }

    along.run(3);
    // Annex II, calculaarea (§4.5): the trapezoids L·W of the edges side by side, then
    // summed one after the other in the seed's order (a sum's rounding depends on it).
    {
        R* const lw = ax; // punt_a is no longer needed
        for (int i = 0; i < end && i < N; i += kSeedLanes) {
            const L x0 = L::load(x + i), y0 = L::load(y + i);
            const L l = x0 - nextLanes(x0, L::load(x + i + kSeedLanes));
            const L w = (y0 + nextLanes(y0, L::load(y + i + kSeedLanes))) * half; // exact halving, as above
            (l * w).store(lw + i);
        }
        R area = 0;
        for (int i = 0; i < N; ++i)
            area = area + lw[i];
        m_aloc = area;
    }

    along.run(4);
    // §4.5: area. F = C·(A_target − A)/N pushes every vertex along the normal of the chord
    // between its neighbours, five times. SeedFrog.java (and the reference trace) applies
    // the correction of vertices 0 and N inside the five passes, both with the normal of
    // the chord v1–v(N−1): with vertex N − 1 before vertex 0 and vertex 1 after vertex N,
    // the chord of vertex i is v(i−1)–v(i+1) for every i in 0…N, and all N + 1 vertices go
    // through the same lanes.
    if (m_components.area && m_areal != m_aloc) {
        R F = m_areaFactor * (m_areal - m_aloc) / R(N);
        // Guard: with an accepted but absurd factor (C and the area both near 1e15) the
        // product overflows R, and ∞ times a zero normal component would be NaN; any F
        // beyond this bound is cut by the ±velmax clamp below anyway.
        const R fmax = std::numeric_limits<R>::max() / R(64);
        if (!(F <= fmax)) F = fmax;
        if (!(F >= -fmax)) F = -fmax;
        const L f = L::splat(F);
        L prevX = L::splat(x[N - 1]), prevY = L::splat(y[N - 1]); // the pack before: N − 1 last
        for (int i = 0; i < end; i += kSeedLanes) {
            const L x0 = L::load(x + i), y0 = L::load(y + i);
            const L beforeX = previousLanes(prevX, x0), beforeY = previousLanes(prevY, y0);
            L nextX = nextLanes(x0, L::load(x + i + kSeedLanes)), nextY = nextLanes(y0, L::load(y + i + kSeedLanes));
            if (holdsLast(i)) {
                const auto last = isLast(i);
                nextX = select(last, L::splat(x[1]), nextX);
                nextY = select(last, L::splat(y[1]), nextY);
            }
            prevX = x0, prevY = y0;
            // The normal (next.y − before.y, −next.x + before.x); −a + b is b − a exactly.
            L nx = nextY - beforeY;
            L ny = beforeX - nextX;
            normalizeLanes(nx, ny, sqrt(nx * nx + ny * ny)); // coincident neighbours: no push
            const L fpx = f * nx, fpy = f * ny;
            L sx = L::load(cx + i), sy = L::load(cy + i);
            for (int j = 0; j < 5; ++j)
                sx = sx + fpx, sy = sy + fpy;
            sx.store(cx + i);
            sy.store(cy + i);
        }
        numAll += 5;
    }

    // Annex II, "Corregim la posicio de les ancores si estan massa lluny": while held,
    // vertices 1 and N−1 are kept within 10 px of the mouse in x and above it, vertices 0
    // and N inside the frame in x and 10 px above the mouse. These corrections do not
    // count in num_correccions (so they are averaged with the others).
    if (held && m_components.grabMode == GrabMode::Anchors) {
        const R mx = m_mouse.x, my = m_mouse.y;
        for (int a : m_anchors) {
            R& ccx = cx[a];
            R& ccy = cy[a];
            const R pxa = x[a], pya = y[a];
            if (a > 0 && a < N) {
                if (pxa < R(mx - R(10))) ccx = R(ccx + R(mx - R(10)) - pxa);
                else if (pxa > R(mx + R(10))) ccx = R(ccx + R(mx + R(10)) - pxa);
                if (pya < 0) ccy = R(ccy - pya);
                else if (pya > R(my - R(1))) ccy = R(ccy + R(my - R(1)) - pya);
            } else {
                if (pxa < 0) ccx = R(ccx - pxa);
                else if (pxa > m_xmax) ccx = R(ccx + m_xmax - pxa);
                if (pya < 0) ccy = R(ccy - pya);
                else if (pya > R(my - R(10))) ccy = R(ccy + R(my - R(10)) - pya);
            }
        }
    }

    along.run(5);
    // The average of the corrections of each vertex, clamped per axis to ±velmax, then
    // §4.2's frame: only the current position is clamped (fita, not fitaant). The count is
    // the same float num_correccions the seed divides by.
    {
        R* __restrict const mxs = lanes(AppliedX);
        R* __restrict const mys = lanes(AppliedY);
        const L nvmax = L::splat(R(-m_velmax));
        const bool bounds = m_components.bounds;
        const L xmax = L::splat(m_xmax), ymax = L::splat(m_ymax);
        const auto finish = [&](int i, const L& mx, const L& my, const L& x1, const L& y1) {
            (bounds ? clampLanes(x1, zero, xmax) : x1).store(x + i);
            (bounds ? clampLanes(y1, zero, ymax) : y1).store(y + i);
            mx.store(mxs + i);
            my.store(mys + i);
        };
        if (held) {
            // The anchors count one more (the seed's num_correccions += 1 of the grab).
            R* __restrict const num = lanes(Num);
            std::fill(num, num + n1, R(numAll));
            for (int a : m_anchors)
                num[a] += 1;
            const L one = L::splat(R(1));
            for (int i = 0; i < end; i += kSeedLanes) {
                const L n = L::load(num + i);
                const auto corrected = ge(n, one); // no correction: 0/0 in the lane, dropped
                const L mx = select(corrected, clampLanes(L::load(cx + i) / n, nvmax, vmax), zero);
                const L my = select(corrected, clampLanes(L::load(cy + i) / n, nvmax, vmax), zero);
                finish(i, mx, my, select(corrected, L::load(x + i) + mx, L::load(x + i)),
                       select(corrected, L::load(y + i) + my, L::load(y + i)));
            }
        } else if (numAll > 0) {
            const L n = L::splat(R(numAll));
            for (int i = 0; i < end; i += kSeedLanes) {
                const L mx = clampLanes(L::load(cx + i) / n, nvmax, vmax);
                const L my = clampLanes(L::load(cy + i) / n, nvmax, vmax);
                finish(i, mx, my, L::load(x + i) + mx, L::load(y + i) + my);
            }
        } else {
            for (int i = 0; i < end; i += kSeedLanes)
                finish(i, zero, zero, L::load(x + i), L::load(y + i));
        }
    }
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
