#pragma once
/// \file outline.h
/// How a body is drawn: the outline curves of §4.9–4.12 and §4.16, computed by the same
/// curve code as the chapter-2 tabs.
///  - Processing's `curveVertex` (Catmull-Rom with τ = 1/2, i.e. curveTightness 0):
///    the seed's body outline and its thick legs (Annex II, `dibuixar`);
///  - a smooth closed Catmull-Rom outline (Def 2.10, closed mode);
///  - the thesis's precomputed Bézier points (§4.9/4.10): the polygon as the control
///    polygon of one Bézier curve, sampled once by De Casteljau;
///  - the per-frame least-squares Bézier fit that §4.9 abandoned as too costly: with the
///    vertex count and the parameters fixed, M⁺ is computed once and each frame costs one
///    small matrix product.

#include "core/base/vec2.h"

#include <Eigen/Core>

#include <vector>

namespace granota {

/// Processing's curveVertex(P_0) … curveVertex(P_{m−1}): a Catmull-Rom curve (τ = 1/2)
/// through P_1 … P_{m−2}; P_0 and P_{m−1} only steer the ends. `samplesPerSegment` ≥ 2
/// points per segment, ends included; joins are not repeated.
std::vector<Point> curveVertexShape(const std::vector<Point>& controls, int samplesPerSegment);

/// Annex II `Poligon.dibuixar`: curveVertex(v_0), v_0 … v_N, curveVertex(v_N) with v_N = v_0.
/// The curve closes at v_0 with a corner there (its end tangents are τ(v_1 − v_0) and
/// τ(v_0 − v_{N−1})), exactly as the seed draws the frog.
std::vector<Point> seedBodyOutline(const std::vector<Point>& vertices, int samplesPerSegment);

/// A smooth closed Catmull-Rom outline through every vertex (Def 2.10, closed mode).
std::vector<Point> closedCatmullRomOutline(const std::vector<Point>& vertices, int samplesPerSegment, double tau = 0.5);

/// Annex II `Pota.dibuixar`: the leg shoulder–elbow–wrist as a thick open shape, each side
/// `factor` px from the bones (factor 7 in the seed), around the wrist and back.
std::vector<Point> legOutline(Point shoulder, Point elbow, Point wrist, double factor, int samplesPerSegment);

/// §4.9: the closed control polygon v_0 … v_{N−1}, v_0 sampled at t = j/samples,
/// j = 0 … samples−1 — the thesis's precomputed points, which then replace the vertices.
std::vector<Point> bezierBodyPoints(const std::vector<Point>& polygon, int samples);
/// The interpolations bezierBodyPoints does for a polygon of `sides` vertices: De Casteljau's
/// triangle on sides + 1 control points, sides·(sides + 1)/2 a sample; what the scene's
/// validation bounds by kMaxBezierOutlineWork (core/base/input_limits.h).
inline double bezierBodyPointsWork(int sides, int samples) { return static_cast<double>(samples) * sides * (sides + 1.0) / 2; }

/// §4.9, the option the thesis abandoned: every frame, the least-squares Bézier curve of
/// degree n through the closed outline v_0 … v_{N−1}, v_0 at uniform parameters
/// (Lemma 2.2, Prop 2.2). M⁺ depends only on N and n, so it is computed once (by a
/// complete orthogonal decomposition); fit() is then P = M⁺Q with no allocation.
class OutlineFitter {
public:
    /// vertexCount ≥ 3, 1 ≤ degree ≤ vertexCount (the closed outline has N + 1 points).
    OutlineFitter(int vertexCount, int degree);
    int vertexCount() const { return m_n; }
    int degree() const { return static_cast<int>(m_pinv.rows()) - 1; }
    /// Control points of the fitted curve, written into `control` (resized once).
    void fit(const std::vector<Point>& vertices, std::vector<Point>& control);
    /// Σ‖Q_i − α(t_i)‖² of the last fit.
    double lastError() const { return m_sse; }

private:
    int m_n;
    Eigen::MatrixXd m_M;           // (N+1) × (n+1)
    Eigen::MatrixXd m_pinv;        // (n+1) × (N+1)
    Eigen::MatrixXd m_Q, m_P, m_R; // (N+1)×2, (n+1)×2, residual (N+1)×2
    double m_sse = 0;
};

} // namespace granota
