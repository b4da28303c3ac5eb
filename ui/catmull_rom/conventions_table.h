#pragma once
/// \file conventions_table.h
/// The Catmull-Rom tab's conventions table (issue 37): the same Catmull-Rom tangent
/// τ(q_{i+1} − q_{i−1}) written with each source's tension, and its value for the curve on
/// the canvas. Checked in each source (docs/spline-families.md, "Tension conventions"):
///  - Granota and the thesis: τ (Def 2.8);
///  - Processing's curveTightness(s): s = 0 is Catmull-Rom, 1 straight lines, τ = (1 − s)/2;
///  - the Primer on Bézier curves (Catmull-Rom section): Bézier points P₂ + (P₃ − P₁)/(6τ_P),
///    so τ = 1/(2τ_P), τ_P = 1/(2τ) (only for τ > 0; τ_P = 1 is τ = 1/2);
///  - d3-shape's curveCardinal.tension(t): k = (1 − t)/6 in P₁ + k(P₂ − P₀), so τ = (1 − t)/2;
///  - Kochanek & Bartels (1984): tension T, τ = (1 − T)/2 (with C = B = 0).

#include "core/exact/rational.h"

#include <QString>
#include <QTableWidget>

#include <optional>
#include <vector>

namespace granota::ui {

/// One source's tension for a given τ.
struct TensionConvention {
    QString source;                ///< who writes it so (translated)
    QString parameter;             ///< its name, e.g. "curveTightness(s)"
    QString fromTau;               ///< the formula from τ, e.g. "s = 1 − 2τ"
    std::optional<Rational> value; ///< for the τ asked; nullopt where the source has none (Primer, τ ≤ 0)
};

/// Every convention for `tau`, Granota's first.
std::vector<TensionConvention> tensionConventions(const Rational& tau);

class ConventionsTable : public QTableWidget {
    Q_OBJECT
public:
    explicit ConventionsTable(QWidget* parent = nullptr);
    /// The conventions of `tau`, named in `what` (e.g. "the selected τ").
    void showTau(const Rational& tau);
    void retranslate();
    const Rational& tau() const { return m_tau; }

private:
    Rational m_tau{1, 2};
};

} // namespace granota::ui
