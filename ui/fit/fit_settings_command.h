#pragma once
/// \file fit_settings_command.h
/// The fitting tab's settings (degree n, parametrization of the t_i, solver, parameter
/// correction) and the undo step of changing them: the settings before and after, like
/// PointsCommand for the points. Consecutive changes of the same setting merge into one
/// step (spinning the degree from 2 to 9 is one undo).

#include "core/curves/fitting/least_squares_fit.h"

#include <QUndoCommand>

#include <functional>

namespace granota::ui {

struct FitSettings {
    int degree = 2;                                            ///< n (the fit uses min(n, k))
    Parametrization parametrization = Parametrization::Uniform; ///< how the t_i are chosen (§2.1.3)
    LeastSquaresSolver solver = LeastSquaresSolver::Qr;        ///< how MP = Q is solved
    bool correctParameters = false;                            ///< iterative parameter correction (beyond the thesis)
    int iterations = 10;                                       ///< at most this many corrections

    friend bool operator==(const FitSettings& a, const FitSettings& b)
    {
        return a.degree == b.degree && a.parametrization == b.parametrization && a.solver == b.solver
               && a.correctParameters == b.correctParameters && a.iterations == b.iterations;
    }
    friend bool operator!=(const FitSettings& a, const FitSettings& b) { return !(a == b); }
};

class FitSettingsCommand : public QUndoCommand {
public:
    /// `apply` sets the tab's settings (and refits); `field` tells which setting changed,
    /// so that repeated changes of the same one merge (−1: never merge).
    FitSettingsCommand(std::function<void(const FitSettings&)> apply, FitSettings before, FitSettings after,
                       const QString& text, int field = -1, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;
    int id() const override { return m_field < 0 ? -1 : kIdBase + m_field; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    static constexpr int kIdBase = 0x46490000; ///< "FI": unique among the tabs' commands
    std::function<void(const FitSettings&)> m_apply;
    FitSettings m_before, m_after;
    int m_field;
};

} // namespace granota::ui
