#pragma once
/// \file knot_continuity_table.h
/// The Catmull-Rom tab's knot table (issue 37): at each knot of the curve drawn, whether it
/// is C⁰, C¹, C² and G¹, G² (core/curves/splines/knot_continuity.h), and the jump of the
/// tangent |p′₊ − p′₋| in the curve's parameter. So Prop 2.3 (C¹ at every knot of a
/// Catmull-Rom curve) is read off row by row, and seen to fail the moment a Kochanek–Bartels
/// continuity C ≠ 0 (a red ✗ under C¹).

#include "core/base/vec2.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/exact/polynomial.h"

#include <QTableWidget>

#include <vector>

namespace granota::ui {

class KnotContinuityTable : public QTableWidget {
    Q_OBJECT
public:
    /// Doubles compare with this relative tolerance (knot_continuity.h).
    static constexpr double kTolerance = 1e-9;
    enum Column { KnotColumn, C0Column, C1Column, C2Column, G1Column, G2Column, JumpColumn, ColumnCount };

    explicit KnotContinuityTable(QWidget* parent = nullptr);

    /// The knots of `segments` (local s ∈ [0, 1], lengths `intervals`, the last joined to the
    /// first when `closedLoop`); segment k starts at point (firstPoint + k) mod pointCount.
    void showCurve(const std::vector<Vec2<Polynomial<double>>>& segments, const std::vector<double>& intervals, bool closedLoop,
                   int firstPoint, int pointCount);
    void retranslate();

    const std::vector<KnotContinuity<double>>& knots() const { return m_knots; }
    /// The point each row's knot sits at (q_i).
    const std::vector<int>& knotPoints() const { return m_knotPoints; }

private:
    void fill();

    std::vector<KnotContinuity<double>> m_knots;
    std::vector<int> m_knotPoints;
};

} // namespace granota::ui
