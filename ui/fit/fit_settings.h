#pragma once
/// \file fit_settings.h
/// The fitting tab's settings (degree n, parametrization of the t_i, solver, parameter
/// correction). Changing them is one undo step, a ValueCommand<FitSettings>
/// (ui/common/value_command.h); consecutive changes of the same setting merge into one step
/// (spinning the degree from 2 to 9 is one undo).

#include "core/curves/fitting/least_squares_fit.h"

namespace granota::ui {

struct FitSettings {
    static constexpr int kMaxIterations = 1000; ///< the most corrections one may ask for (docs/file-formats.md)

    int degree = 2;                                             ///< n (the fit uses min(n, k))
    Parametrization parametrization = Parametrization::Uniform; ///< how the t_i are chosen (§2.1.3)
    LeastSquaresSolver solver = LeastSquaresSolver::Qr;         ///< how MP = Q is solved
    bool correctParameters = false;                             ///< iterative parameter correction (beyond the thesis)
    int iterations = 10;                                        ///< at most this many corrections

    friend bool operator==(const FitSettings& a, const FitSettings& b)
    {
        return a.degree == b.degree && a.parametrization == b.parametrization && a.solver == b.solver &&
               a.correctParameters == b.correctParameters && a.iterations == b.iterations;
    }
    friend bool operator!=(const FitSettings& a, const FitSettings& b) { return !(a == b); }
};

} // namespace granota::ui
