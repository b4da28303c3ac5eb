#pragma once
/// \file fit_exact_view.h
/// The fitting tab's side panel text (docs/tabs.md): the parameters t_i, the chord lengths
/// d_i in simplest radical form, the matrices M, MᵀM, (MᵀM)⁻¹, M⁺ (Ex 2.7, Ex 2.8), the
/// control points P = M⁺Q and the curve α(t) in powers of t — as fractions when the data
/// and the parameters are rational, in decimals otherwise — with the thesis's slips
/// (Ex 2.8's −1636/105, Ex 2.9's √85) noted where the data are the thesis's, and chord-length t_i
/// in radicals beside the ones Ex 2.9/2.10 print (radical_sum.h). It only
/// formats: every value comes from the core.

#include "core/exact/exact_cost.h"
#include "core/exact/rational.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "ui/fit/fit_settings.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

class FitExactView {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::FitExactView)
public:
    /// Exact matrices are shown up to this many data points (larger ones do not read).
    static constexpr int kMaxExactPoints = 13;
    /// Parameters, chord lengths and decimal matrices are listed up to this many points.
    static constexpr int kMaxListedPoints = 40;
    /// A matrix M with more rows or columns than kMaxListedPoints is shown as its top-left
    /// corner of at most this many rows and columns, with its size stated.
    static constexpr int kMatrixCorner = 8;

    struct Input {
        const std::vector<Point>* points = nullptr; ///< Q_0..Q_k as the editor holds them
        /// Their exact values (PointEditor::allExactPoints()); nullopt when one has none.
        std::optional<std::vector<RPoint>> exact;
        int degree = 0; ///< the degree actually fitted
        Parametrization parametrization = Parametrization::Uniform;
        bool correctParameters = false;
        const FitResult* fit = nullptr; ///< nullptr when the fit failed
        bool showMatrices = false;
        /// The most estimated work of the exact fit (core/exact/exact_cost.h); beyond it the
        /// results are shown in decimals with a note. Always kMaxExactWork in the tab.
        double exactBudget = kMaxExactWork;
    };

    /// The panel's HTML (ExactPanel helpers).
    static QString html(const Input& input);
};

} // namespace granota::ui
