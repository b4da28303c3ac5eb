#pragma once
/// \file vec2.h
/// A point or vector of the plane over any scalar S: double for drawing and fitting,
/// Rational for the thesis's exact tables, Polynomial<Rational> for the symbolic
/// De Casteljau levels P_i^r(t) of Ex 2.2 and Ex 2.3.

#include <cmath>

namespace granota {

template <class S> struct Vec2 {
    S x{};
    S y{};

    Vec2() = default;
    Vec2(S x_, S y_) : x(std::move(x_)), y(std::move(y_)) {}

    Vec2& operator+=(const Vec2& o)
    {
        x += o.x;
        y += o.y;
        return *this;
    }
    Vec2& operator-=(const Vec2& o)
    {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    friend Vec2 operator+(Vec2 a, const Vec2& b)
    {
        a += b;
        return a;
    }
    friend Vec2 operator-(Vec2 a, const Vec2& b)
    {
        a -= b;
        return a;
    }
    friend Vec2 operator-(const Vec2& a) { return Vec2(S(-a.x), S(-a.y)); }
    friend bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
    friend bool operator!=(const Vec2& a, const Vec2& b) { return !(a == b); }
};

/// Scalar times vector. The scalar is of the same type S on purpose (no mixed
/// expression-template surprises with GMP): callers write S(…) explicitly.
template <class S> Vec2<S> operator*(const S& s, const Vec2<S>& v) { return Vec2<S>(S(s * v.x), S(s * v.y)); }
template <class S> Vec2<S> operator*(const Vec2<S>& v, const S& s) { return s * v; }

using Point = Vec2<double>;

inline double dot(const Point& a, const Point& b) { return a.x * b.x + a.y * b.y; }
inline double cross(const Point& a, const Point& b) { return a.x * b.y - a.y * b.x; }
/// Euclidean length without overflow for coordinates up to 1e300.
inline double norm(const Point& a) { return std::hypot(a.x, a.y); }
inline double distance(const Point& a, const Point& b) { return norm(a - b); }
/// The unit vector along `d`, as Processing's PVector.normalize: a zero vector stays zero.
inline Point normalized(const Point& d)
{
    const double n = norm(d);
    return n > 0 ? Point(d.x / n, d.y / n) : d;
}
inline bool isFinite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

} // namespace granota
