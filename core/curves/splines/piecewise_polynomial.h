#pragma once
/// \file piecewise_polynomial.h
/// A function spline (Def 2.2, Def 2.3): knots x_0 < x_1 < … < x_k and one polynomial
/// piece s_{i+1} on each interval [x_i, x_{i+1}] (the thesis numbers pieces from 1; the
/// vector from 0, so pieces[i] is the thesis's s_{i+1}).
///
/// A piece is stored in one of two forms:
///  - global powers of x, as Ex 2.1 prints them: s_1(x) = −132/53 x² + 238/53 x + 1.
///    Exact for Rational, and what a student compares with the thesis;
///  - local powers of (x − x_i) (`localOrigin = true`): numerically sound for doubles,
///    since expanding around a far-away origin cancels digits (x = 1e6 and a cubic term).
/// globalPiece()/localPiece() convert between the two with the Taylor shift.

#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

template <class S> struct PiecewisePolynomial {
    std::vector<S> knots;              ///< x_0 < x_1 < … < x_k, k ≥ 1
    std::vector<Polynomial<S>> pieces; ///< pieces[i] lives on [knots[i], knots[i+1]]
    bool localOrigin = false;          ///< pieces in powers of (x − knots[i]) instead of x

    int pieceCount() const { return static_cast<int>(pieces.size()); }
    /// Knots and pieces agree in number and the knots increase strictly.
    bool isValid() const
    {
        if (pieces.empty() || knots.size() != pieces.size() + 1)
            return false;
        for (std::size_t i = 0; i + 1 < knots.size(); ++i)
            if (!(knots[i] < knots[i + 1]))
                return false;
        return true;
    }
    const S& domainBegin() const { return knots.front(); }
    const S& domainEnd() const { return knots.back(); }

    /// Index of the piece used for x: the half-open [x_i, x_{i+1}) that holds x, the last
    /// piece for x = x_k (Ex 2.1's convention [0,1), [1,2), [2,3]). Outside the domain the
    /// first or last piece (extrapolation).
    int pieceIndex(const S& x) const
    {
        assert(!pieces.empty() && knots.size() == pieces.size() + 1); // O(1): this is the hot path
        const auto it = std::upper_bound(knots.begin(), knots.end(), x);
        const auto i = static_cast<int>(it - knots.begin()) - 1;
        return std::clamp(i, 0, pieceCount() - 1);
    }

    /// Piece i evaluated at the global abscissa x, whatever its storage form.
    S evaluatePiece(int i, const S& x) const
    {
        const auto& p = pieces[static_cast<std::size_t>(i)];
        return localOrigin ? p(S(x - knots[static_cast<std::size_t>(i)])) : p(x);
    }

    /// s(x).
    S operator()(const S& x) const { return evaluatePiece(pieceIndex(x), x); }

    /// Piece i in powers of x (Ex 2.1's form): q(x − x_i) = q.shifted(−x_i).
    Polynomial<S> globalPiece(int i) const
    {
        const auto& p = pieces[static_cast<std::size_t>(i)];
        return localOrigin ? p.shifted(S(-knots[static_cast<std::size_t>(i)])) : p;
    }
    /// Piece i in powers of (x − x_i): p(u + x_i) = p.shifted(x_i).
    Polynomial<S> localPiece(int i) const
    {
        const auto& p = pieces[static_cast<std::size_t>(i)];
        return localOrigin ? p : p.shifted(knots[static_cast<std::size_t>(i)]);
    }

    /// The same function with every piece in global (or every piece in local) powers.
    PiecewisePolynomial toGlobal() const
    {
        PiecewisePolynomial out{knots, {}, false};
        for (int i = 0; i < pieceCount(); ++i)
            out.pieces.push_back(globalPiece(i));
        return out;
    }
    PiecewisePolynomial toLocal() const
    {
        PiecewisePolynomial out{knots, {}, true};
        for (int i = 0; i < pieceCount(); ++i)
            out.pieces.push_back(localPiece(i));
        return out;
    }

    /// s′, piece by piece: d/dx q(x − x_i) = q′(x − x_i), so the storage form is kept.
    PiecewisePolynomial derivative() const
    {
        PiecewisePolynomial out{knots, {}, localOrigin};
        out.pieces.reserve(pieces.size());
        for (const auto& p : pieces)
            out.pieces.push_back(p.derivative());
        return out;
    }

    /// Highest degree of the pieces: the order δ_s of the spline (Def 2.2).
    int order() const
    {
        int d = -1;
        for (const auto& p : pieces)
            d = std::max(d, p.degree());
        return d;
    }
};

extern template struct PiecewisePolynomial<double>;
extern template struct PiecewisePolynomial<Rational>;

} // namespace granota
