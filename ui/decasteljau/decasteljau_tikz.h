#pragma once
/// \file decasteljau_tikz.h
/// The De Casteljau tab's picture in TikZ (File ▸ Export ▸ TikZ), from the same
/// DeCasteljauScene the canvas draws and in its order: the control polygon, the construction,
/// the comb, the tight box, the curve, the inflections and cusps, the tangent and the normal,
/// the osculating circle, the points, the hodograph's inset and the key.

#include "ui/decasteljau/decasteljau_scene.h"

#include <QRectF>

namespace granota::ui {

class TikzWriter;

/// `content` is the model rectangle the tab frames: an osculating circle much larger than it is left out.
void writeDeCasteljauTikz(TikzWriter& w, const DeCasteljauScene& s, const QRectF& content);

} // namespace granota::ui
