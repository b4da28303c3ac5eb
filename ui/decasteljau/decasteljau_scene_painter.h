#pragma once
/// \file decasteljau_scene_painter.h
/// The De Casteljau tab's picture drawn from a DeCasteljauScene (decasteljau_scene.h), one
/// drawing for the screen and every export (File ▸ Export renders the canvas): the layers
/// under the handles in order — the curves of `desglossar`, the curve traced up to t, the
/// comb, the tight box and its extrema, the construction of Def 2.4, the split at t, the
/// inflections and cusps, the osculating circle, the normal, the tangent and c(t) — then, over
/// the handles, the hodograph's inset and the key in the corners where they cover least.

#include "ui/common/canvas_legend.h"
#include "ui/common/canvas_style.h"
#include "ui/decasteljau/decasteljau_scene.h"

#include <QColor>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace granota::ui {

class ViewTransform;

inline const QColor kDeCasteljauTangent{0x6a, 0x3d, 0x9a};
inline const QColor kDeCasteljauNormal{0xb1, 0x59, 0x28};
inline const QColor kDeCasteljauCircle{0x7b, 0x8d, 0x2a};
inline const QColor kDeCasteljauBox{0x5e, 0x6a, 0x78};
inline const QColor kDeCasteljauExtremumEdge{0x1c, 0x2a, 0x33}; ///< the edge of an extremum's ◆
inline const QColor kDeCasteljauInflection{0xd6, 0x27, 0x8b};
inline const QColor kDeCasteljauCusp{0xc0, 0x20, 0x20};
/// The halves of the split at t: [0, t] and [t, 1].
inline const QColor kDeCasteljauSplit[2] = {QColor(0xc0, 0x39, 0x8b), QColor(0x1b, 0x9e, 0x77)};

/// One layer of the picture.
using DeCasteljauLayer = void (*)(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s);
/// The layers under the handles, bottom first.
const std::vector<DeCasteljauLayer>& deCasteljauLayers();

/// The key: the levels', step curves' and halves' colours and the overlays shown.
CanvasLegend deCasteljauLegend(const DeCasteljauScene& s);
/// What the key and the inset should not cover in a view: the curve's samples, the
/// construction's points, the handles with their labels (`labelPrefix` + i) and c(t) with its label.
CanvasLegendObstacles deCasteljauObstacles(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                           const CanvasStyle& style);
/// Where the key goes: the corner that covers no handle, label, c(t) or inset if one can.
CanvasLegendBox deCasteljauLegendBox(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                     const CanvasStyle& style);
/// Where the hodograph's inset is drawn (empty when it is hidden): the corner that covers
/// least (the lower right winning a tie, then lower left, upper right, upper left).
QRectF deCasteljauHodographInset(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                 const CanvasStyle& style);
/// The hodograph c′ in its inset, with its own construction at t and c′(t) as a vector.
void drawDeCasteljauHodographInset(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s,
                                   const QString& labelPrefix);
/// The side of the squares that mark the halves' control points (over the level's dots).
double deCasteljauSplitSquareSide(const CanvasStyle& style);
/// A line with a filled head at `to`.
void drawDeCasteljauArrow(QPainter& p, const QPointF& from, const QPointF& to, double head);

} // namespace granota::ui
