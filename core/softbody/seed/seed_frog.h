#pragma once
/// \file seed_frog.h
/// The `seed` solver's frog: the `Granota` of Annex II (§4.16) — a SeedBody and four
/// SeedLegs whose shoulders are recomputed from the body after every body step. The legs
/// hang from the body but do not act on it (the seed has no feedback from legs to body),
/// so the body of a frog moves exactly as a lone SeedBody. The four legs are kept side by
/// side in SIMD lanes (core/softbody/seed/seed_leg_lanes.h); legs() is refreshed from them when read
/// (each leg's shoulder() is where it was attached in the last step).
///
/// The legs' part of a step waits for the body's, and the body's next step does not wait
/// for the legs. So step() leaves the legs' step owed, with their shoulders set, and pays
/// it inside the next step(), between the parts of the body's step (SeedBody::stepWith):
/// the processor works on both chains at once. legs() pays what is owed before it
/// answers, so what anyone reads is exactly Annex II's frog after each step.

#include "core/softbody/seed/seed_body.h"
#include "core/softbody/seed/seed_leg.h"
#include "core/softbody/seed/seed_leg_lanes.h"

#include <array>
#include <vector>

namespace granota {

/// Leg indices, in the order of Annex II's arrays and of the trace columns.
namespace seedleg {
enum Index : int { FrontRight = 0, FrontLeft = 1, BackRight = 2, BackLeft = 3 };
}

template <class R> class SeedFrog {
public:
    using Vec = Vec2<R>;

    /// The frog as SeedFrog.java's main builds it: the body at FrogParams::center with
    /// radius FrogParams::radius and initial velocity v0, the four legs straight along +x
    /// from the centre. Fails with the message of checkSeedParams.
    static Expected<SeedFrog> create(const FrogParams& params, SeedComponents components = {});

    /// Annex II, Granota.actualitza: the body, then the shoulders, then the legs in the
    /// order front right, back right, front left, back left (dd, dr, ed, er).
    void step();

    const SeedBody<R>& body() const { return m_body; }
    SeedBody<R>& body() { return m_body; }
    /// Front right, front left, back right, back left; empty when the legs are off.
    const std::vector<SeedLeg<R>>& legs() const
    {
        if (m_legsStale)
            syncLegs();
        return m_legs;
    }

    /// The sketch's mouse and space-bar handlers (see SeedBody): they act on the body only;
    /// a respawn leaves the legs where they are, and they follow at the next step.
    bool press(const Point& mouse) { return m_body.press(mouse); }
    void move(const Point& mouse) { m_body.move(mouse); }
    void release() { m_body.release(); }
    bool respawn(const Point& centre) { return m_body.respawn(centre); }
    void releaseSpawn() { m_body.releaseSpawn(); }

    const FrogParams& params() const { return m_body.params(); }
    SeedComponents components() const { return m_body.components(); }

private:
    SeedFrog(SeedBody<R> body, std::vector<SeedLeg<R>> legs);
    void syncLegs() const;   // m_legs from m_legLanes
    void settleLegs() const; // the owed legs' step, if any

    SeedBody<R> m_body;
    mutable SeedLegLanes<R> m_legLanes;     // the legs between steps
    mutable bool m_legsOwed = false;        // m_legLanes is one step behind (shoulders set)
    mutable std::vector<SeedLeg<R>> m_legs; // stale after a step until asked for
    mutable bool m_legsStale = false;
    std::array<int, 6> m_attach{}; // the seed's vertices 2, 3, 4, 6, 7, 8 for this N
};

extern template class SeedFrog<float>;
extern template class SeedFrog<double>;

} // namespace granota
