#pragma once
/// \file seed_leg.h
/// The `seed` solver's leg: the `Pota` of Annex II, a pendulum of three joints — the
/// shoulder (`muscle`, driven from outside), the elbow (`colze`) and the wrist (`canell`),
/// the last two Verlet points (§4.13–4.16). Each step the segment lengths are restored at
/// once by moving the joint with Desp (position and previous position, §4.14), the angles
/// are clamped with acos (§4.15) and a wrist below the floor is lifted, moving the elbow
/// along the circle round the shoulder (the quadratic of Annex II).
///
/// Usable on its own, with the shoulder anywhere (the pendulum scenes drive it with a
/// fixed or mouse-driven shoulder), or as one of the frog's four legs (core/softbody/seed/seed_frog.h).
/// Note that the seed keeps only the wrist above the floor: a leg hanging from a body
/// pressed against a side wall reaches past that wall (SeedFrog.java does so as well);
/// every joint stays within upper + lower of its shoulder.

#include "core/softbody/seed/seed_body.h"

namespace granota {

template <class R> class SeedLegLanes;

template <class R> class SeedLeg {
public:
    using Vec = Vec2<R>;

    /// The leg params.legs[index] (0 front right, 1 front left, 2 back right, 3 back left)
    /// hanging from `shoulder`, straight along +x as SeedFrog.java's main builds it:
    /// elbow at shoulder + (upper, 0), wrist at shoulder + (upper + lower, 0), at rest.
    /// Gravity, friction, velmax and the floor (height − 1) come from params.
    static Expected<SeedLeg> create(const FrogParams& params, int index, const Point& shoulder, SeedComponents components = {});
    /// The same with any LegParams (a pendulum scene's own lengths and limits).
    static Expected<SeedLeg> create(const FrogParams& params, const LegParams& leg, const Point& shoulder,
                                    SeedComponents components = {});

    /// Annex II, Pota.actualitza(mov): the shoulder moves to `shoulder`, then one step.
    void step(const Point& shoulder);

    Vec shoulder() const { return m_muscle; }
    Vec elbow() const { return m_colze.pos; }
    Vec wrist() const { return m_canell.pos; }
    const SeedVertex<R>& elbowVertex() const { return m_colze; }
    const SeedVertex<R>& wristVertex() const { return m_canell; }
    /// moll1, moll2: the rest lengths, measured as the seed does (dist of the first pose).
    R upperLength() const { return m_moll1; }
    R lowerLength() const { return m_moll2; }
    /// shoulder, elbow, wrist as doubles (for drawing).
    std::vector<Point> joints() const;

    SeedComponents components() const { return m_components; }

private:
    friend class SeedLegLanes<R>; // the frog's legs are stepped side by side, in lanes
    SeedLeg() = default;
    void precomputeLimits();
    void moveShoulder(const Point& shoulder);

    SeedComponents m_components;
    Vec m_muscle;
    SeedVertex<R> m_colze, m_canell;
    Vec m_grav, m_freg;
    R m_velmax = 0;
    R m_moll1 = 0, m_moll2 = 0;
    R m_angmin1 = 0, m_angmax1 = 0, m_angmin2 = 0, m_angmax2 = 0;
    R m_floor = 0; // height − 1
    double m_width = 0;
    // §4.15's clamps without acos, sin or cos in the step (precomputeLimits), for the
    // limits shoulder max, −shoulder min, elbow max, −elbow min:
    R m_limitRatio[4] = {}; // the largest Δy/|Δ| whose float acos exceeds the limit
    R m_limitOffX[4] = {};  // R(sin(limit))·moll: where the clamp puts the joint, …
    R m_limitOffY[4] = {};  // … and R(cos(limit))·moll
};

extern template class SeedLeg<float>;
extern template class SeedLeg<double>;

} // namespace granota
