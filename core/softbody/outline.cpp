#include "core/softbody/outline.h"

#include "core/curves/splines/catmull_rom.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/least_squares_fit.h"

#include <Eigen/QR>

#include <cassert>
#include <cmath>

namespace granota {

namespace {

/// Appends a segment's samples, skipping its first point when it repeats the last one.
void appendSegment(std::vector<Point>& out, const Vec2<Polynomial<double>>& seg, int samples)
{
    for (int j = out.empty() ? 0 : 1; j < samples; ++j) {
        const double s = j == samples - 1 ? 1.0 : static_cast<double>(j) / (samples - 1);
        out.emplace_back(seg.x(s), seg.y(s));
    }
}


} // namespace

std::vector<Point> curveVertexShape(const std::vector<Point>& controls, int samplesPerSegment)
{
    assert(samplesPerSegment >= 2);
    std::vector<Point> out;
    if (controls.size() < 4)
        return controls.size() >= 2 ? std::vector<Point>(controls.begin() + 1, controls.end() - 1) : out;
    const double tau = curveTightnessToTau(0.0); // Processing's default curveTightness(0): τ = 1/2
    for (std::size_t i = 1; i + 2 < controls.size(); ++i)
        appendSegment(out, catmullRomSegment(controls[i - 1], controls[i], controls[i + 1], controls[i + 2], tau),
                      samplesPerSegment);
    return out;
}

std::vector<Point> seedBodyOutline(const std::vector<Point>& vertices, int samplesPerSegment)
{
    if (vertices.empty())
        return {};
    std::vector<Point> controls;
    controls.reserve(vertices.size() + 3);
    controls.push_back(vertices.front());
    controls.insert(controls.end(), vertices.begin(), vertices.end());
    controls.push_back(vertices.front()); // v_N = v_0
    controls.push_back(vertices.front());
    return curveVertexShape(controls, samplesPerSegment);
}

std::vector<Point> closedCatmullRomOutline(const std::vector<Point>& vertices, int samplesPerSegment, double tau)
{
    std::vector<Point> out;
    auto segments = catmullRomSegments(vertices, tau, CatmullRomMode::Closed, 0.0);
    if (!segments)
        return vertices; // fewer than 3 points or non-finite: the polygon itself
    for (const auto& seg : *segments)
        appendSegment(out, seg, samplesPerSegment);
    return out;
}

std::vector<Point> legOutline(Point m, Point e, Point w, double f, int samplesPerSegment)
{
    const Point d1 = normalized(e - m), d2 = normalized(w - e);
    // Annex II, Pota.dibuixar: offsets perpendicular to each bone, averaged at the elbow.
    const Point mPlus(m.x + d1.y * f, m.y - d1.x * f), mMinus(m.x - d1.y * f, m.y + d1.x * f);
    const Point ePlus(e.x + (d1.y + d2.y) * f / 2, e.y - (d1.x + d2.x) * f / 2);
    const Point eMinus(e.x - (d1.y + d2.y) * f / 2, e.y + (d1.x + d2.x) * f / 2);
    const Point wPlus(w.x + d2.y * f, w.y - d2.x * f), wMinus(w.x - d2.y * f, w.y + d2.x * f);
    return curveVertexShape({mPlus, mPlus, ePlus, wPlus, wMinus, eMinus, mMinus, mPlus}, samplesPerSegment);
}

std::vector<Point> bezierBodyPoints(const std::vector<Point>& polygon, int samples)
{
    assert(samples >= 1);
    if (polygon.empty())
        return {};
    std::vector<Point> control(polygon);
    control.push_back(polygon.front()); // closed: the curve starts and ends at v_0
    std::vector<Point> out, work(control.size());
    out.reserve(static_cast<std::size_t>(samples));
    for (int j = 0; j < samples; ++j) {
        work = control;
        out.push_back(deCasteljauInPlace(work, static_cast<double>(j) / samples));
    }
    return out;
}

OutlineFitter::OutlineFitter(int vertexCount, int degree) : m_n(vertexCount)
{
    assert(vertexCount >= 3 && degree >= 1 && degree <= vertexCount);
    std::vector<double> t(static_cast<std::size_t>(vertexCount + 1));
    for (int i = 0; i <= vertexCount; ++i)
        t[static_cast<std::size_t>(i)] = static_cast<double>(i) / vertexCount;
    m_M = bernsteinMatrix(t, degree);
    m_pinv = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(m_M).pseudoInverse();
    m_Q.resize(vertexCount + 1, 2);
    m_P.resize(degree + 1, 2);
    m_R.resize(vertexCount + 1, 2);
}

void OutlineFitter::fit(const std::vector<Point>& vertices, std::vector<Point>& control)
{
    assert(static_cast<int>(vertices.size()) == m_n);
    for (int i = 0; i < m_n; ++i) {
        m_Q(i, 0) = vertices[static_cast<std::size_t>(i)].x;
        m_Q(i, 1) = vertices[static_cast<std::size_t>(i)].y;
    }
    m_Q.row(m_n) = m_Q.row(0);
    m_P.noalias() = m_pinv * m_Q; // P = M⁺Q (Nota 2.2)
    m_R.noalias() = m_M * m_P;
    m_R -= m_Q;
    m_sse = m_R.squaredNorm();
    control.resize(static_cast<std::size_t>(m_P.rows()));
    for (int j = 0; j < m_P.rows(); ++j)
        control[static_cast<std::size_t>(j)] = Point(m_P(j, 0), m_P(j, 1));
}

} // namespace granota
