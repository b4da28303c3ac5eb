#pragma once
/// \file conic_section.h
/// A conic arc as a rational quadratic Bézier curve in standard form (beyond the thesis, issue
/// 36; Farin, "Curves and Surfaces for CAGD", §13.4–13.5; Piegl & Tiller, "The NURBS Book",
/// §7.2–7.3): the ends P_0, P_2, the corner P_1 where the end tangents meet, the weights
/// (1, w, 1):
///   c(t) = ((1−t)² P_0 + 2w t(1−t) P_1 + t² P_2) / ((1−t)² + 2w t(1−t) + t²).
/// Its kind is its middle weight's: an ellipse for w < 1 (a circle for the right w), a
/// parabola for w = 1 (a polynomial curve), a hyperbola for w > 1 (Farin, §13.4), and a
/// degenerate (straight) conic when the three points are collinear.
///
/// The implicit equation comes from barycentric coordinates (τ_0, τ_1, τ_2) with respect to
/// the triangle P_0 P_1 P_2: a point of the curve has τ_0 = (1−t)²/D, τ_1 = 2w t(1−t)/D,
/// τ_2 = t²/D, hence
///   τ_1² = 4 w² τ_0 τ_2   (Farin, §13.4),
/// and with τ_i = L_i(x, y)/Δ, L_i affine (twice a signed triangle area), Δ twice the area of
/// P_0 P_1 P_2, the conic A x² + B xy + C y² + D x + E y + F = 0 is L_1² − 4w² L_0 L_2 = 0.
/// Templated on the scalar: Rational points and a rational w give exact coefficients.

#include "core/base/vec2.h"

#include <array>
#include <vector>

namespace granota {

enum class ConicKind { Ellipse, Parabola, Hyperbola, Degenerate };

/// "ellipse", "parabola", "hyperbola", "degenerate".
inline const char* conicKindName(ConicKind k)
{
    switch (k) {
    case ConicKind::Ellipse: return "ellipse";
    case ConicKind::Parabola: return "parabola";
    case ConicKind::Hyperbola: return "hyperbola";
    case ConicKind::Degenerate: break;
    }
    return "degenerate";
}

/// A x² + B xy + C y² + D x + E y + F = 0.
template <class S> struct ImplicitConic {
    S a{}, b{}, c{}, d{}, e{}, f{};
    /// The left-hand side at p: 0 on the conic.
    S operator()(const Vec2<S>& p) const { return S(a * p.x * p.x + b * p.x * p.y + c * p.y * p.y + d * p.x + e * p.y + f); }
    /// B² − 4AC: negative for an ellipse, 0 for a parabola, positive for a hyperbola.
    S discriminant() const { return S(b * b - S(4) * a * c); }
};

template <class S> struct ConicSection {
    std::array<Vec2<S>, 3> points; ///< P_0, P_1 (the tangents' corner), P_2
    S weight = S(1);               ///< w > 0, the middle weight (the ends' are 1)

    std::vector<Vec2<S>> controlPoints() const { return {points[0], points[1], points[2]}; }
    std::vector<S> weights() const { return {S(1), weight, S(1)}; }

    /// The kind by the middle weight (Farin, §13.4), degenerate for collinear points.
    ConicKind kind() const
    {
        if (twiceArea() == S(0))
            return ConicKind::Degenerate;
        if (weight < S(1))
            return ConicKind::Ellipse;
        if (weight == S(1))
            return ConicKind::Parabola;
        return ConicKind::Hyperbola;
    }

    /// Δ = (P_1 − P_0) × (P_2 − P_0), twice the signed area of the triangle.
    S twiceArea() const
    {
        const Vec2<S> u = points[1] - points[0], v = points[2] - points[0];
        return S(u.x * v.y - u.y * v.x);
    }

    /// L_1² − 4w² L_0 L_2 (the header), with L_i = Δ·τ_i.
    ImplicitConic<S> implicitEquation() const
    {
        // L(X) = (A − X) × (B − X) = α x + β y + γ, α = A.y − B.y, β = B.x − A.x, γ = A × B:
        // twice the signed area of A B X, the barycentric coordinate of the vertex opposite A B.
        struct Affine {
            S alpha, beta, gamma;
        };
        const auto area = [](const Vec2<S>& A, const Vec2<S>& B) {
            return Affine{S(A.y - B.y), S(B.x - A.x), S(A.x * B.y - A.y * B.x)};
        };
        const Affine l0 = area(points[1], points[2]), l1 = area(points[2], points[0]), l2 = area(points[0], points[1]);
        const S k = S(S(4) * weight * weight);
        ImplicitConic<S> q;
        // The product of two affine forms, term by term: L L′ = αα′ x² + (αβ′ + βα′) xy + ββ′ y² + …
        q.a = S(l1.alpha * l1.alpha - k * l0.alpha * l2.alpha);
        q.b = S(S(2) * l1.alpha * l1.beta - k * S(l0.alpha * l2.beta + l0.beta * l2.alpha));
        q.c = S(l1.beta * l1.beta - k * l0.beta * l2.beta);
        q.d = S(S(2) * l1.alpha * l1.gamma - k * S(l0.alpha * l2.gamma + l0.gamma * l2.alpha));
        q.e = S(S(2) * l1.beta * l1.gamma - k * S(l0.beta * l2.gamma + l0.gamma * l2.beta));
        q.f = S(l1.gamma * l1.gamma - k * l0.gamma * l2.gamma);
        return q;
    }
};

} // namespace granota
