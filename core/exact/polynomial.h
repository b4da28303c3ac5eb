#pragma once
/// \file polynomial.h
/// Univariate polynomials c_0 + c_1 t + … + c_n t^n over any scalar S (double, long
/// double, Rational). The thesis writes every curve in powers of t (Ex 2.2: c(t) = (2 −
/// 12t − 6t² + 52t³ − 43t⁴, …)); Polynomial<Rational> reproduces those exactly, and since
/// it has + − × and S(1) it can itself be the scalar of De Casteljau's algorithm.

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <vector>

namespace granota {

template <class S> class Polynomial {
public:
    Polynomial() = default;
    /// The constant polynomial c (so that S(1), S(0) work in generic code).
    Polynomial(S c) : m_c{std::move(c)} { trim(); }
    Polynomial(std::initializer_list<S> coefficients) : m_c(coefficients) { trim(); }
    explicit Polynomial(std::vector<S> coefficients) : m_c(std::move(coefficients)) { trim(); }
    /// Allows Polynomial<Rational>(1) and Polynomial<double>(0).
    template <class I, class = std::enable_if_t<std::is_integral_v<I>>> Polynomial(I c) : Polynomial(S(c)) {}

    /// The polynomial t.
    static Polynomial identity() { return Polynomial(std::vector<S>{S(0), S(1)}); }

    /// Degree; the zero polynomial has degree -1.
    int degree() const { return static_cast<int>(m_c.size()) - 1; }
    bool isZero() const { return m_c.empty(); }
    /// Coefficient of t^k (0 beyond the degree).
    S coefficient(int k) const { return k >= 0 && k <= degree() ? m_c[static_cast<std::size_t>(k)] : S(0); }
    const std::vector<S>& coefficients() const { return m_c; }
    /// Coefficients c_0..c_n padded with zeros to exactly n+1 entries (n >= degree()).
    std::vector<S> coefficients(int n) const
    {
        std::vector<S> out(static_cast<std::size_t>(n + 1), S(0));
        for (int k = 0; k <= std::min(n, degree()); ++k)
            out[static_cast<std::size_t>(k)] = m_c[static_cast<std::size_t>(k)];
        return out;
    }

    /// Horner's rule.
    template <class T> T operator()(const T& t) const
    {
        T value(0);
        for (auto it = m_c.rbegin(); it != m_c.rend(); ++it)
            value = T(value * t + T(*it));
        return value;
    }

    Polynomial derivative() const
    {
        std::vector<S> d;
        for (int k = 1; k <= degree(); ++k)
            d.push_back(S(S(k) * m_c[static_cast<std::size_t>(k)]));
        return Polynomial(std::move(d));
    }

    /// p(t + a), the Taylor shift: re-expands the polynomial around a.
    Polynomial shifted(const S& a) const
    {
        std::vector<S> c = m_c;
        const int n = degree();
        for (int i = 0; i < n; ++i)
            for (int k = n - 1; k >= i; --k)
                c[static_cast<std::size_t>(k)] += S(a * c[static_cast<std::size_t>(k + 1)]);
        return Polynomial(std::move(c));
    }

    Polynomial& operator+=(const Polynomial& o)
    {
        if (o.m_c.size() > m_c.size())
            m_c.resize(o.m_c.size(), S(0));
        for (std::size_t k = 0; k < o.m_c.size(); ++k)
            m_c[k] += o.m_c[k];
        trim();
        return *this;
    }
    Polynomial& operator-=(const Polynomial& o)
    {
        if (o.m_c.size() > m_c.size())
            m_c.resize(o.m_c.size(), S(0));
        for (std::size_t k = 0; k < o.m_c.size(); ++k)
            m_c[k] -= o.m_c[k];
        trim();
        return *this;
    }
    friend Polynomial operator+(Polynomial a, const Polynomial& b)
    {
        a += b;
        return a;
    }
    friend Polynomial operator-(Polynomial a, const Polynomial& b)
    {
        a -= b;
        return a;
    }
    friend Polynomial operator-(const Polynomial& a) { return Polynomial() - a; }
    friend Polynomial operator*(const Polynomial& a, const Polynomial& b)
    {
        if (a.isZero() || b.isZero())
            return Polynomial();
        std::vector<S> c(a.m_c.size() + b.m_c.size() - 1, S(0));
        for (std::size_t i = 0; i < a.m_c.size(); ++i)
            for (std::size_t j = 0; j < b.m_c.size(); ++j)
                c[i + j] += S(a.m_c[i] * b.m_c[j]);
        return Polynomial(std::move(c));
    }
    Polynomial& operator*=(const Polynomial& o) { return *this = *this * o; }
    friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.m_c == b.m_c; }
    friend bool operator!=(const Polynomial& a, const Polynomial& b) { return !(a == b); }

private:
    void trim()
    {
        while (!m_c.empty() && m_c.back() == S(0))
            m_c.pop_back();
    }
    std::vector<S> m_c; // m_c[k] is the coefficient of t^k; no trailing zeros
};

} // namespace granota
