#pragma once
/// \file stage_body.h
/// The body of chapter 4's first five stages, before Verlet integration (§4.6) replaced
/// explicit velocities:
///  - §4.1 a regular polygon whose radius follows the mouse, r = |mouseY − h/2|;
///  - §4.2 gravity by the MRUA update v(t) = v(t−1) + g, X(t) = X(t−1) + v(t), kept inside
///    the frame with min/max;
///  - §4.3 bouncing: a vertex leaving the frame is put back on the edge and that component
///    of its velocity is reversed and multiplied by the friction f; a click respawns;
///  - §4.4 springs between consecutive vertices, corrected through the midpoint targets of
///    Annex II and applied as a velocity ("una correcció en forma de vector velocitat"),
///    so the correction is gradual, not immediate;
///  - §4.5 area conservation: the trapezoid-rule area and corrections along the edge
///    normals, averaged with the spring corrections per vertex.
/// Annex II keeps only the final program; these stages are rebuilt from the text of
/// §4.1–4.5 with the final program's formulas where the text names them.

#include "core/base/expected.h"
#include "core/softbody/scenes/frog_params.h"

#include <vector>

namespace granota {

struct StageComponents {
    bool gravity = false; ///< §4.2: v += g every step
    bool bounds = false;  ///< §4.2: the vertices stay in [0, width−1] × [0, height−1]
    bool bounce = false;  ///< §4.3: leaving the frame reverses and damps the velocity
    bool springs = false; ///< §4.4: edge springs, corrected as velocities
    bool area = false;    ///< §4.5: area corrections along the edge normals
};

class StageBody {
public:
    /// Rejects what makes no sense: fewer than 3 sides, a frame under 1 px, a negative
    /// radius or target area, non-finite numbers.
    static Expected<StageBody> create(const FrogParams& params, StageComponents components);

    void step();
    /// §4.1: the radius follows the mouse's height, r = |mouseY − h/2|, the polygon is
    /// rebuilt around the same centre.
    void followMouse(Point mouse);
    /// §4.3: a click puts a new polygon (the initial size and velocity) at the point.
    void respawn(Point centre);

    const std::vector<Point>& vertices() const { return m_x; }
    const std::vector<Point>& velocities() const { return m_v; }
    const FrogParams& params() const { return m_p; }
    const StageComponents& components() const { return m_c; }
    double radius() const { return m_radius; }

private:
    StageBody(const FrogParams& p, StageComponents c) : m_p(p), m_c(c) {}
    void build(Point centre, double radius, Point velocity);

    FrogParams m_p;
    StageComponents m_c;
    double m_radius = 0;
    Point m_centre;
    std::vector<Point> m_x, m_v;
    std::vector<Point> m_correction; // scratch, kept to avoid allocating per step
    std::vector<int> m_count;
};

/// The checks every body scene shares: the parameters a frog scene accepts.
Expected<void> validateFrogParams(const FrogParams& p);

} // namespace granota
