#pragma once
/// \file outline_sampling.h
/// The outlines of outline.h sampled into buffers that the caller keeps, for the live frog
/// canvas (60 frames per second, docs/scenes.md): once the buffers have grown to size, drawing a
/// frame allocates nothing. Each function writes exactly the points of its counterpart in
/// outline.h / de_casteljau.h (test_outline_sampling checks it), from the same M(τ) of
/// Lemma 2.3 and the same De Casteljau (Def 2.4); `out` is cleared first, its capacity kept.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// seedBodyOutline(vertices, samplesPerSegment): Annex II `Poligon.dibuixar`, Processing's
/// curveVertex (τ = 1/2) with the seed's corner at v_0.
void sampleSeedBodyOutline(const std::vector<Point>& vertices, int samplesPerSegment, std::vector<Point>& out);

/// closedCatmullRomOutline(vertices, samplesPerSegment, tau): Def 2.10, closed mode. Fewer
/// than 3 vertices, a non-finite vertex or τ, or an overflow: the polygon itself.
void sampleClosedCatmullRomOutline(const std::vector<Point>& vertices, int samplesPerSegment, double tau,
                                   std::vector<Point>& out);

/// legOutline(shoulder, elbow, wrist, factor, samplesPerSegment): Annex II `Pota.dibuixar`.
void sampleLegOutline(Point shoulder, Point elbow, Point wrist, double factor, int samplesPerSegment, std::vector<Point>& out);

/// sampleBezier(control, samples): c(j/(samples − 1)), j = 0 … samples − 1 (samples ≥ 2),
/// by De Casteljau in `work` (scratch, resized once). An empty control polygon gives nothing.
void sampleBezierCurve(const std::vector<Point>& control, int samples, std::vector<Point>& work, std::vector<Point>& out);

} // namespace granota
