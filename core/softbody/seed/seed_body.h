#pragma once
/// \file seed_body.h
/// The `seed` solver's body: the `Poligon` of Annex II ("Codi del programa Granota"),
/// headless and deterministic. The seed is reproduced operation by operation — the same
/// order of floating-point operations, the same temporaries, the same five-pass loops —
/// so that with R = float it follows Processing's single-precision run of the sketch
/// (reference/seed_frog_trace.csv, produced by reference/SeedFrog.java). R = double is the
/// same algorithm in double precision.
///
/// Where SeedFrog.java and the Annex text differ, SeedFrog.java is followed, because it
/// produced the reference trace; the mouse handling it leaves out (grabbing, anchors,
/// space-bar respawn) follows the Annex. Places where the seed would divide by zero or
/// produce NaN/∞ are guarded; each guard is marked "Guard:" in the .cpp and only acts
/// where the seed itself would not give a finite result.

#include "core/base/expected.h"
#include "core/softbody/scenes/frog_params.h"
#include "core/softbody/scenes/grab_mode.h"
#include "core/softbody/seed/seed_lanes_avx2.h"
#include "core/base/vec2.h"

#include <cmath>
#include <optional>
#include <vector>

namespace granota {

/// Which parts of Annex II run. All on is Annex II exactly; the earlier stages of
/// chapter 4 switch parts off (§4.2 has no springs, §4.4 no area, …).
struct SeedComponents {
    bool gravity = true;     ///< g added in every Verlet step (§4.2)
    bool bounds = true;      ///< the frame clamp `fita` of the body and the floor of the legs (§4.2)
    bool springs = true;     ///< edge springs through the midpoint targets punt_a/punt_b (§4.4)
    bool area = true;        ///< area correction along the edge normals (§4.5)
    bool legs = true;        ///< the four `Pota` (§4.16); off: the frog is just the body
    bool grab = true;        ///< mouse grabbing with anchors (§4.6, §4.7); off: respawn does not hold
    bool angleLimits = true; ///< the acos angle clamps of the legs (§4.15)
    /// Beyond the seed: keep the legs' joints in the frame too (the seed keeps only the
    /// wrist above the floor, so with some constants a leg reaches past the side of the
    /// window). Only a scene naming the component `legs-in-frame` turns it on; the frog
    /// scene does not, so that the seed's traces are reproduced exactly.
    bool clampLegs = false;
    /// Which vertices the grab holds (§4.6 all, §4.7 those above the mouse, Annex II's
    /// fixed anchors, which also get the extra anchor clamps of the final program).
    GrabMode grabMode = GrabMode::Anchors;
};

/// The checks the three seed factories share. Rejected: non-finite values
/// (InvalidInput); sides outside [3, 10000]; width or height below 1; a negative radius,
/// target area, spring length, velmax or leg length; any value beyond 1e15 in magnitude
/// (OutOfRange). The last bound keeps every square of a distance finite in single
/// precision (1e15² · 4 < 3.4e38), so no later product can overflow to ∞ and then meet a
/// zero (∞·0 = NaN); a frame or a gravity of 1e15 px is far beyond any screen.
std::optional<Error> checkSeedParams(const FrogParams& params);

/// Annex II's `Vertex`: the current and previous positions of a Verlet point.
template <class R> struct SeedVertex {
    Vec2<R> pos;  ///< posicio
    Vec2<R> prev; ///< posicioant

    /// Annex II, Vertex.Verlet (§4.6): x' = x + f∘(x − x_prev) + g, then the new position
    /// is clamped per axis to [x − velmax, x + velmax] so that the step cannot diverge.
    void verlet(const Vec2<R>& f, const Vec2<R>& g, R velmax)
    {
        Vec2<R> n(R(pos.x + f.x * (pos.x - prev.x) + g.x), R(pos.y + f.y * (pos.y - prev.y) + g.y));
        const R xmax = pos.x + velmax, xmin = pos.x - velmax, ymax = pos.y + velmax, ymin = pos.y - velmax;
        if (n.x < xmin)
            n.x = xmin;
        else if (n.x > xmax)
            n.x = xmax;
        if (n.y < ymin)
            n.y = ymin;
        else if (n.y > ymax)
            n.y = ymax;
        prev = pos;
        pos = n;
    }
    /// Annex II, Vertex.Desp: moves both positions, so the velocity is kept.
    void desp(const Vec2<R>& mov)
    {
        prev = Vec2<R>(R(prev.x + mov.x), R(prev.y + mov.y));
        pos = Vec2<R>(R(pos.x + mov.x), R(pos.y + mov.y));
    }
    /// Annex II, Vertex.fita: clamps the current position to a box (the previous one is
    /// left alone, so hitting a wall keeps the velocity that pushed into it, §4.3).
    void fita(R xmin, R xmax, R ymin, R ymax) { clampTo(pos, xmin, xmax, ymin, ymax); }
    /// Annex II, Vertex.fitaant: the same for the previous position.
    void fitaant(R xmin, R xmax, R ymin, R ymax) { clampTo(prev, xmin, xmax, ymin, ymax); }

private:
    static void clampTo(Vec2<R>& p, R xmin, R xmax, R ymin, R ymax)
    {
        if (p.x < xmin)
            p.x = xmin;
        else if (p.x > xmax)
            p.x = xmax;
        if (p.y < ymin)
            p.y = ymin;
        else if (p.y > ymax)
            p.y = ymax;
    }
};

/// Processing's maths in precision R: the argument goes to double and the result comes
/// back to R, as `(float) Math.sin(a)` in Processing. For R = double these are plain calls.
namespace seedmath {
template <class R> R sin(R a) { return R(std::sin(double(a))); }
template <class R> R cos(R a) { return R(std::cos(double(a))); }
template <class R> R acos(R a) { return R(std::acos(double(a))); }
template <class R> R sqrt(R a) { return R(std::sqrt(double(a))); }
/// Processing's dist(a, b, c, d) = sqrt((c − a)² + (d − b)²), in R.
template <class R> R dist(R a, R b, R c, R d) { return sqrt(R((c - a) * (c - a) + (d - b) * (d - b))); }
/// PVector.normalize: divides by the length unless it is 0 or 1 — a zero vector stays
/// zero, which is how the seed survives coincident points.
template <class R> void normalize(Vec2<R>& v)
{
    const R m = sqrt(R(v.x * v.x + v.y * v.y));
    if (m != 0 && m != 1) {
        v.x /= m;
        v.y /= m;
    }
}
} // namespace seedmath

/// The body of the frog: N vertices kept as the seed keeps them, N + 1 with vertex N a
/// copy of vertex 0 that is updated alongside it (closing the polygon).
template <class R> class SeedBody {
public:
    using Vec = Vec2<R>;

    /// A body built as SeedFrog.java's main builds it: a regular N-gon of radius r around
    /// FrogParams::center, first vertex at the top, with initial velocity v0.
    static Expected<SeedBody> create(const FrogParams& params, SeedComponents components = {});

    /// A body whose rest shape is any polygon (offsets from its centre, in order): the
    /// Bézier body of §4.9 and the shapes of §5.2.3. `params.sides` is ignored.
    static Expected<SeedBody> createFromShape(const FrogParams& params, const std::vector<Point>& shape,
                                              SeedComponents components = {});

    /// Annex II, Poligon.inicialitza(center, v_ini): the regular polygon at `centre`, each
    /// vertex's previous position set back by v_ini, both clamped to the frame; not grabbed.
    void initialise(const Vec& centre, const Vec& v0);

    /// Annex II, Poligon.actualitza: one frame (Verlet, springs, anchors, area, clamps).
    void step();
    /// step() with another computation's six parts, along.run(0) … along.run(5), run
    /// between its own: the processor then works on both at once (the frog's legs, whose
    /// chains of square roots and divisions would otherwise leave it waiting). `along` may
    /// not touch this body. Instantiated for SeedLegLanes<R>::Step.
    template <class Along> void stepWith(Along& along);

    /// mousePressed + mantindreagafat: grabs the body if `mouse` (clamped to the frame) is
    /// inside it and it is not held already. Returns whether it is now held by this press.
    bool press(const Point& mouse);
    /// The mouse moved (mouseX, mouseY of the sketch): the grab pulls towards it.
    void move(const Point& mouse);
    /// mouseReleased + allibera.
    void release();
    /// The space bar (keyPressed): unless the body is held, inicialitza(mouse, (0, 0)) at
    /// `centre` (clamped to the frame) and, with the grab component, hold it there until
    /// releaseSpawn(). Returns whether the body was respawned.
    bool respawn(const Point& centre);
    /// keyReleased + allibera.
    void releaseSpawn();

    bool grabbed() const { return m_grabbed; }
    /// The mouse position the anchors pull towards (in the frame).
    Point mouse() const { return Point(double(m_mouse.x), double(m_mouse.y)); }

    int sides() const { return m_n; }
    /// The N distinct vertices (vertex N, the seed's copy of vertex 0, is left out).
    std::vector<Point> vertices() const;
    /// The previous positions of the N distinct vertices (velocity = vertex − previous).
    std::vector<Point> previousVertices() const;
    /// All N + 1 vertices of the seed, in precision R. Between steps the body keeps its
    /// vertices as lanes (positionsX/Y below); this copy is refreshed when asked.
    const std::vector<SeedVertex<R>>& seedVertices() const
    {
        if (m_vertStale)
            syncVertices();
        return m_vert;
    }
    /// The current x (and y) of the N + 1 vertices, contiguous: the step's own arrays.
    const R* positionsX() const { return lanes(X); }
    const R* positionsY() const { return lanes(Y); }
    /// The correction applied to each of the N + 1 vertices in the last step (averaged and
    /// clamped to ±velmax per axis); zero where none was applied.
    const std::vector<Vec>& corrections() const;
    /// Annex II, calculaarea: the trapezoid rule of §4.5 on the current vertices, in R.
    R area() const;
    /// The area Aloc measured during the last step (before its corrections).
    R lastMeasuredArea() const { return m_aloc; }
    R targetArea() const { return m_areal; }
    /// The anchor distances estruc of the current grab (indexed by vertex, 0..N).
    const std::vector<R>& anchorDistances() const { return m_estruc; }

    const FrogParams& params() const { return m_params; }
    SeedComponents components() const { return m_components; }

private:
    SeedBody(const FrogParams& params, SeedComponents components);
    // step() with a fixed number of packs of lanes (0: as many as the body needs).
    template <int Packs, class Along> void stepPacks(Along& along);
#ifdef GRANOTA_SEED_AVX2
    // The same with eight lanes per pack (R = float, a processor with AVX2).
    template <int Packs, class Along> GRANOTA_AVX2_TARGET void stepPacksWide(Along& along);
#endif
    struct NothingAlong {
        void run(int) {}
    };
    void holdAt(const Vec& clau); // mantindreagafat
    void finishInitialise();      // the end of inicialitza, shared by both rest shapes
    Vec clampMouse(const Point& p) const;
    void syncVertices() const; // m_vert from the lane arrays

    FrogParams m_params;
    SeedComponents m_components;
    int m_n = 0;
    Vec m_gravity, m_friction;
    R m_areaFactor = 0, m_velmax = 0, m_radius = 0, m_springLength = 0;
    R m_xmax = 0, m_ymax = 0; // width − 1, height − 1
    R m_areal = 0, m_aloc = 0;
    // N + 1: a copy of the lane arrays, stale after a step until asked for.
    mutable std::vector<SeedVertex<R>> m_vert;
    mutable bool m_vertStale = false;
    std::vector<R> m_estruc;    // N + 1
    std::vector<Point> m_shape; // rest shape around the centre; empty: the regular N-gon
    std::vector<int> m_anchors; // the vertices held by the current grab
    bool m_grabbed = false;
    Vec m_mouse;
    // The body's state is kept as a "structure of arrays" (all x, then all y, …) so that
    // four vertices go through each operation of the step at once (core/softbody/seed/seed_lanes.h);
    // X, Y, PrevX and PrevY hold the vertices between steps. The arrays live in one buffer,
    // sized once: a step allocates nothing.
    enum LaneArray { X, Y, PrevX, PrevY, CorrX, CorrY, PuntAX, PuntAY, PuntBX, PuntBY, Num, AppliedX, AppliedY, LaneArrayCount };
    R* lanes(LaneArray a) { return m_lanes.data() + std::size_t(a) * m_stride; }
    const R* lanes(LaneArray a) const { return m_lanes.data() + std::size_t(a) * m_stride; }
    std::vector<R> m_lanes;
    std::size_t m_stride = 0;
    mutable std::vector<Vec> m_applied; // corrections(), filled from AppliedX/Y when asked
};

extern template class SeedBody<float>;
extern template class SeedBody<double>;

} // namespace granota
