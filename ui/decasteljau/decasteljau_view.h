#pragma once
/// \file decasteljau_view.h
/// What the De Casteljau tab shows of its curve (docs/tabs.md): the sampling precision (the
/// thesis's Matlab `part`), the control points (`puntsvis`), the construction of Def 2.4, the
/// curves of the first 1…n + 1 points (`desglossar`), the tangent, the split at t, snapping,
/// and the overlays beyond the thesis (normal, osculating circle, curvature comb and its scale,
/// bounding box, inflections and cusps, hodograph, playing at constant speed). A plain value:
/// one undo step holds it before and after, the document keeps it (docs/file-formats.md).
/// The parameter t is the curve's (curve_model.h), not the view's.

#include <QJsonObject>
#include <QString>

#include <optional>

namespace granota::ui {

struct DeCasteljauView {
    static constexpr int kDefaultSamples = 200; ///< Matlab `part`: the curve through part + 1 points
    static constexpr int kMinSamples = 1;       ///< one interval: the chord P_0 P_n
    static constexpr int kMaxSamples = 5000;    ///< 200 points × 5000 samples: about 1e8 operations

    int samples = kDefaultSamples;
    bool controlPoints = true; ///< the handles, their labels and the polygon (Matlab `puntsvis`)
    bool construction = true;  ///< every level P_i^r(t) (Def 2.4)
    bool stepByStep = false;   ///< the curves of the first 1, 2, …, n + 1 points (Matlab `desglossar`)
    bool tangent = false;
    bool split = false;
    bool snap = false; ///< dragged and added points snap to the grid
    bool normal = false;
    bool osculatingCircle = false;
    bool comb = false;
    double combScale = 0; ///< the comb's scale (curvature_comb_scale_box.h); 0 is automatic
    bool boundingBox = false;
    bool inflections = false; ///< inflections and cusps
    bool hodograph = false;
    bool constantSpeed = false; ///< playing moves c(t) by equal steps of arc length

    /// The same view with `samples` and `combScale` brought into their ranges (a scale that
    /// is not a finite number is automatic).
    DeCasteljauView clamped() const;

    friend bool operator==(const DeCasteljauView& a, const DeCasteljauView& b);
    friend bool operator!=(const DeCasteljauView& a, const DeCasteljauView& b) { return !(a == b); }
};

/// The keys of the tab's part of a document (docs/file-formats.md): `samples`,
/// `control_points`, `construction`, `stepByStep`, `tangent`, `split`, `snap`, `normal`,
/// `osculatingCircle`, `curvatureComb`, `curvatureCombScale`, `boundingBox`, `inflections`,
/// `hodograph`, `constantSpeed`.
void writeDeCasteljauView(const DeCasteljauView& view, QJsonObject& json);
/// Reads them (an absent key keeps the default: older documents); nullopt with the reason,
/// translated, in `error`.
std::optional<DeCasteljauView> readDeCasteljauView(const QJsonObject& json, QString& error);

} // namespace granota::ui
