#include "core/softbody/outline_sampling.h"

#include "core/curves/splines/catmull_rom.h"
#include "core/curves/bezier/de_casteljau.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

/// Processing's curveVertex tension: curveTightness(0), τ = 1/2.
constexpr double kProcessingTau = curveTightnessToTau(0.0);

bool finiteCoefficients(const std::array<Point, 4>& c)
{
    for (const Point& p : c)
        if (!isFinite(p))
            return false;
    return true;
}

/// Appends the segment of Lemma 2.3 through p1 (s = 0) and p2 (s = 1) at s = j/(S − 1), by
/// Horner in each coordinate as Polynomial::operator() does; the first sample is skipped
/// when `out` already ends at the join (as outline.cpp's appendSegment). Returns false when
/// a coefficient overflows.
bool appendCatmullRomSegment(std::vector<Point>& out, Point p0, Point p1, Point p2, Point p3, double tau, int samples,
                             bool checkFinite)
{
    const std::array<Point, 4> c = catmullRomCoefficients(p0, p1, p2, p3, tau);
    if (checkFinite && !finiteCoefficients(c))
        return false;
    for (int j = out.empty() ? 0 : 1; j < samples; ++j) {
        const double s = j == samples - 1 ? 1.0 : static_cast<double>(j) / (samples - 1);
        double x = 0, y = 0;
        for (int r = 3; r >= 0; --r) {
            x = x * s + c[static_cast<std::size_t>(r)].x;
            y = y * s + c[static_cast<std::size_t>(r)].y;
        }
        out.emplace_back(x, y);
    }
    return true;
}


} // namespace

void sampleSeedBodyOutline(const std::vector<Point>& v, int samplesPerSegment, std::vector<Point>& out)
{
    assert(samplesPerSegment >= 2);
    out.clear();
    if (v.empty())
        return;
    // curveVertex(v_0), v_0 … v_{N−1}, v_N = v_0, curveVertex(v_N): controls c_0 … c_{N+2}.
    const std::size_t n = v.size(), count = n + 3;
    const auto control = [&](std::size_t k) -> const Point& { return k >= 1 && k <= n ? v[k - 1] : v[0]; };
    for (std::size_t i = 1; i + 2 < count; ++i)
        appendCatmullRomSegment(out, control(i - 1), control(i), control(i + 1), control(i + 2), kProcessingTau,
                                samplesPerSegment, false);
}

void sampleClosedCatmullRomOutline(const std::vector<Point>& v, int samplesPerSegment, double tau, std::vector<Point>& out)
{
    assert(samplesPerSegment >= 2);
    out.clear();
    const auto polygon = [&] { out.assign(v.begin(), v.end()); };
    if (v.size() < 3 || !std::isfinite(tau) || !std::all_of(v.begin(), v.end(), [](const Point& p) { return isFinite(p); }))
        return polygon();
    // Def 2.10, option 1 plus the closing segment: segment i from q_{i−2}, q_{i−1}, q_i, q_{i+1} (mod n + 1).
    const long size = static_cast<long>(v.size());
    const auto q = [&](long j) -> const Point& { return v[static_cast<std::size_t>(((j % size) + size) % size)]; };
    for (long i = 1; i <= size; ++i)
        if (!appendCatmullRomSegment(out, q(i - 2), q(i - 1), q(i), q(i + 1), tau, samplesPerSegment, true))
            return polygon();
}

void sampleLegOutline(Point m, Point e, Point w, double f, int samplesPerSegment, std::vector<Point>& out)
{
    assert(samplesPerSegment >= 2);
    out.clear();
    const Point d1 = normalized(e - m), d2 = normalized(w - e);
    // Annex II, Pota.dibuixar: offsets perpendicular to each bone, averaged at the elbow.
    const Point mPlus(m.x + d1.y * f, m.y - d1.x * f), mMinus(m.x - d1.y * f, m.y + d1.x * f);
    const Point ePlus(e.x + (d1.y + d2.y) * f / 2, e.y - (d1.x + d2.x) * f / 2);
    const Point eMinus(e.x - (d1.y + d2.y) * f / 2, e.y + (d1.x + d2.x) * f / 2);
    const Point wPlus(w.x + d2.y * f, w.y - d2.x * f), wMinus(w.x - d2.y * f, w.y + d2.x * f);
    const std::array<Point, 8> c{mPlus, mPlus, ePlus, wPlus, wMinus, eMinus, mMinus, mPlus};
    for (std::size_t i = 1; i + 2 < c.size(); ++i)
        appendCatmullRomSegment(out, c[i - 1], c[i], c[i + 1], c[i + 2], kProcessingTau, samplesPerSegment, false);
}

void sampleBezierCurve(const std::vector<Point>& control, int samples, std::vector<Point>& work, std::vector<Point>& out)
{
    assert(samples >= 2);
    out.clear();
    if (control.empty())
        return;
    work.resize(control.size());
    const double u0 = 1.0 / (samples - 1);
    for (int j = 0; j < samples; ++j) {
        const double t = j == samples - 1 ? 1.0 : j * u0; // exact end, as sampleBezier
        std::copy(control.begin(), control.end(), work.begin());
        out.push_back(deCasteljauInPlace(work, t));
    }
}

} // namespace granota
