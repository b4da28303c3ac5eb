#pragma once
/// \file family_report.h
/// The exact side panel of the Catmull-Rom tab when a family other than Catmull-Rom is chosen
/// (curve_family.h; issue 37): the panel describes the curve on the canvas, never the τ
/// curves under another family's name. Cardinal and Kochanek–Bartels: the tangents at every
/// point (in and out for KB) and each segment's Hermite data and Bézier control points, as
/// exact fractions when the points are small fractions and the spacing uniform (computed by
/// the core in Rational: cardinal_spline.h, kochanek_bartels.h, hermite_segment.h), else in
/// decimals from the scene. Hermite: the student's tangents and the same segments. The C²
/// spline in the plane and function data: what their panels on the left show, in a sentence.

#include "core/exact/exact_point.h"
#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

class FamilyReport {
    Q_DECLARE_TR_FUNCTIONS(FamilyReport)
public:
    /// `exact`: every point exactly (PointEditor::allExactPoints()), or nullopt.
    static QString html(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exact,
                        const CatmullRomSettings& settings, const CatmullRomScene& scene);
};

} // namespace granota::ui
