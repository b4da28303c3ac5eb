#pragma once
// The energy-drift report's series in closed form (docs/work-precision.md), computed here
// from the recurrences' exact solutions, not by stepping: x'' = −x, x0 = 1, v0 = 0,
// E = (v² + x²)/2, error E/E0 − 1 at step n, h = 0.1. Shared by test_energy_drift (the core)
// and test_cli_report (the CSV granota-cli writes).
#include <cmath>
#include <string>

namespace energy_drift {

inline constexpr double h = 0.1;

/// Verlet's recurrence x_{n+1} = (2 − h²) x_n − x_{n−1} is a rotation by θ with
/// cos θ = 1 − h²/2, i.e. sin(θ/2) = h/2 (this form keeps θ well conditioned).
inline double theta() { return 2 * std::asin(h / 2); }

/// The positions from x_{−1} = x_0 = 1 (Annex II's start with v0 = 0; also semi-implicit
/// Euler's, whose v_n = (x_n − x_{n−1})/h): x_n = cos nθ + B sin nθ, and x_{−1} = 1 gives
/// B = (cos θ − 1)/sin θ = −tan(θ/2).
inline double annexIIPosition(double n) { return std::cos(n * theta()) - std::tan(theta() / 2) * std::sin(n * theta()); }

/// Explicit Euler: (x, v) ↦ (x + h v, v − h x) multiplies x² + v² by exactly 1 + h².
inline double explicitEuler(double n) { return std::expm1(n * std::log1p(h * h)); }

/// Semi-implicit Euler: the positions above, v_n the backward difference.
inline double semiImplicitEuler(double n)
{
    const double x = annexIIPosition(n), v = (x - annexIIPosition(n - 1)) / h;
    return x * x + v * v - 1;
}

/// Verlet with the Taylor start x_{−1} = 1 − h²/2 = cos θ: x_n = cos nθ, and with the centred
/// velocity v_n = (x_{n+1} − x_{n−1})/(2h) = −sin nθ · sin θ / h, sin²θ = h² − h⁴/4:
/// E/E0 − 1 = −(h²/4) sin² nθ.
inline double verletTaylor(double n)
{
    const double s = std::sin(n * theta());
    return -(h * h / 4) * s * s;
}

/// Verlet with Annex II's start, the centred velocity from the positions above.
inline double verletAnnexII(double n)
{
    const double x = annexIIPosition(n), v = (annexIIPosition(n + 1) - annexIIPosition(n - 1)) / (2 * h);
    return x * x + v * v - 1;
}

/// RK4 on x'' = −x is the linear map R(ih) on x + i·v (up to conjugation), with
/// R(z) = 1 + z + z²/2 + z³/6 + z⁴/24: the energy is multiplied by g = |R(ih)|² each step,
/// g = (1 − h²/2 + h⁴/24)² + (h − h³/6)² = 1 − h⁶/72 + h⁸/576 (the h² and h⁴ terms cancel),
/// written as g − 1 so that its logarithm keeps its digits.
inline double rk4(double n)
{
    const double h2 = h * h, gMinus1 = -h2 * h2 * h2 / 72 + h2 * h2 * h2 * h2 / 576;
    return std::expm1(n * std::log1p(gMinus1));
}

/// The closed form of the report's method named `method` (its series' name).
inline double closedForm(const std::string& method, double n)
{
    if (method == "explicit Euler")
        return explicitEuler(n);
    if (method == "semi-implicit Euler")
        return semiImplicitEuler(n);
    if (method == "Verlet")
        return verletTaylor(n);
    if (method == "Verlet (Annex II start)")
        return verletAnnexII(n);
    return rk4(n);
}

} // namespace energy_drift
