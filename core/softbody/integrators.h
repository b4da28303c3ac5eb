#pragma once
/// \file integrators.h
/// Time integrators for a particle x'' = a(x, v): the ones the thesis uses and the ones a
/// student should compare them with (docs/work-precision.md).
///  - explicit Euler:       x' = x + h v,          v' = v + h a(x, v)
///  - semi-implicit Euler:  v' = v + h a(x, v),    x' = x + h v'   — the "MRUA" update of
///    §4.2 (v(t) = v(t−1) + g, X(t) = X(t−1) + v(t), with h = 1)
///  - Verlet (Def 3.1):     x_{t+1} = 2 x_t − x_{t−1} + h² a_t, no velocity needed
///  - classical Runge–Kutta of order 4 on (x, v).
/// Verlet and semi-implicit Euler are symplectic (second and first order, energy stays
/// bounded); explicit Euler gains energy every step; RK4 is fourth order but costs four
/// evaluations of a per step.

#include "core/base/vec2.h"

#include <optional>
#include <string>
#include <string_view>

namespace granota {

enum class Integrator { ExplicitEuler, SemiImplicitEuler, Verlet, Rk4 };

/// "euler", "semi-implicit-euler", "verlet", "rk4", exactly (case and blanks count);
/// nullopt for anything else.
std::optional<Integrator> parseIntegrator(std::string_view name);
std::string integratorName(Integrator i);
/// Evaluations of the acceleration per step (what a step costs).
int evaluationsPerStep(Integrator i);

/// A particle's state. `previous` is Verlet's x_{t−1}; the other integrators keep it equal
/// to the position before the step, so switching integrators mid-run is possible.
struct ParticleState {
    Point position;
    Point velocity;
    Point previous;
};

/// Starts a particle at x0 with velocity v0: Verlet's x_{−1} = x0 − h v0 + ½ h² a(x0, v0)
/// (the Taylor start that makes Verlet second-order from the first step).
template <class Accel> ParticleState startParticle(Point x0, Point v0, double h, Accel a)
{
    const Point a0 = a(x0, v0);
    return {x0, v0, Point(x0.x - h * v0.x + 0.5 * h * h * a0.x, x0.y - h * v0.y + 0.5 * h * h * a0.y)};
}

/// Starts a particle as Annex II starts its vertices: x_{−1} = x0 − h v0 (the previous
/// position one velocity step back, without the ½ h² a0 term). With this start Def 3.1's
/// x_{t+1} = 2x_t − x_{t−1} + h² a_t gives exactly the positions of semi-implicit Euler,
/// the update the thesis derives it from (x_1 = x0 + h v0 + h² a0 for both, and the
/// recurrences agree from there): first order, not second (docs/thesis-errata.md).
template <class Accel> ParticleState startParticleAnnexII(Point x0, Point v0, double h, Accel a)
{
    ParticleState s = startParticle(x0, v0, h, a);
    s.previous = Point(x0.x - h * v0.x, x0.y - h * v0.y);
    return s;
}

/// One step of size h. Verlet has no velocity of its own; for readouts (energy) it is
/// estimated as (x_{t+1} − x_t)/h + ½ h a_t, which is v(t+1) to O(h²) — the plain
/// difference quotient is v(t+½) and would show a spurious first-order energy error.
template <class Accel> void integrate(Integrator method, ParticleState& s, double h, Accel a)
{
    const Point x = s.position, v = s.velocity;
    switch (method) {
    case Integrator::ExplicitEuler: {
        const Point acc = a(x, v);
        s.position = Point(x.x + h * v.x, x.y + h * v.y);
        s.velocity = Point(v.x + h * acc.x, v.y + h * acc.y);
        s.previous = x;
        break;
    }
    case Integrator::SemiImplicitEuler: {
        const Point acc = a(x, v);
        s.velocity = Point(v.x + h * acc.x, v.y + h * acc.y);
        s.position = Point(x.x + h * s.velocity.x, x.y + h * s.velocity.y);
        s.previous = x;
        break;
    }
    case Integrator::Verlet: { // Def 3.1
        const Point acc = a(x, v);
        const Point next(2 * x.x - s.previous.x + h * h * acc.x, 2 * x.y - s.previous.y + h * h * acc.y);
        s.velocity = Point((next.x - x.x) / h + 0.5 * h * acc.x, (next.y - x.y) / h + 0.5 * h * acc.y);
        s.previous = x;
        s.position = next;
        break;
    }
    case Integrator::Rk4: {
        const Point k1x = v, k1v = a(x, v);
        const Point x2(x.x + 0.5 * h * k1x.x, x.y + 0.5 * h * k1x.y), v2(v.x + 0.5 * h * k1v.x, v.y + 0.5 * h * k1v.y);
        const Point k2x = v2, k2v = a(x2, v2);
        const Point x3(x.x + 0.5 * h * k2x.x, x.y + 0.5 * h * k2x.y), v3(v.x + 0.5 * h * k2v.x, v.y + 0.5 * h * k2v.y);
        const Point k3x = v3, k3v = a(x3, v3);
        const Point x4(x.x + h * k3x.x, x.y + h * k3x.y), v4(v.x + h * k3v.x, v.y + h * k3v.y);
        const Point k4x = v4, k4v = a(x4, v4);
        s.position = Point(x.x + h / 6 * (k1x.x + 2 * k2x.x + 2 * k3x.x + k4x.x),
                           x.y + h / 6 * (k1x.y + 2 * k2x.y + 2 * k3x.y + k4x.y));
        s.velocity = Point(v.x + h / 6 * (k1v.x + 2 * k2v.x + 2 * k3v.x + k4v.x),
                           v.y + h / 6 * (k1v.y + 2 * k2v.y + 2 * k3v.y + k4v.y));
        s.previous = x;
        break;
    }
    }
}

} // namespace granota
