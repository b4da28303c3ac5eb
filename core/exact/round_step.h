#pragma once
/// \file round_step.h
/// Round steps — 1, 2 or 5 × 10^k — held exactly: the spacing of the canvas's grid and the
/// step of the arrow keys' nudge (docs/tabs.md). A nudge of 0.1 is the rational 1/10, not the
/// double 0.1, so that a point at −9/5 nudged right is −17/10 exactly, and a point keeps the
/// small fraction the exact panels read from it (rational_approximation.h).

#include "core/exact/rational.h"

namespace granota {

/// mantissa × 10^exponent, with mantissa 1, 2 or 5.
struct RoundStep {
    int mantissa = 1;
    int exponent = 0;
    /// The step as a rational: 5 × 10^−2 is 1/20 exactly.
    Rational exact() const;
    /// The double nearest to exact().
    double value() const;
    RoundStep timesTen() const { return {mantissa, exponent + 1}; }
};

/// The largest round step not above `limit`, and the smallest not below it. `limit` must be
/// finite and positive; the exponent stays within ±300 (RoundStep{1, 0} for a bad limit).
RoundStep roundStepAtMost(double limit);
RoundStep roundStepAtLeast(double limit);

/// The next multiple of `step` (> 0) from `v` in the direction of `sign` (+1 up, −1 down), exactly:
/// a value on the step's grid moves by one step, a value between two multiples moves to the
/// next one in that direction (so 1/3 nudged up by 1/10 is 2/5).
Rational nextMultiple(const Rational& v, const Rational& step, int sign);
/// The multiple of `step` (> 0) nearest to `v` (a half goes up).
Rational nearestMultiple(const Rational& v, const Rational& step);

} // namespace granota
