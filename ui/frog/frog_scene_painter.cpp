#include "ui/frog/frog_scene_painter.h"

#include "core/base/math_constants.h"
#include "core/softbody/outline.h"
#include "core/softbody/outline_sampling.h"
#include "core/softbody/simulation.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// Samples of the per-frame least-squares Bézier curve (§4.9's abandoned option).
constexpr int kFitSamples = 160;
/// The head image's size in Annex II belongs to the frog's target area, Areal = 20000 px².
constexpr double kSeedTargetArea = 20000;
/// The thinnest the bare polygon of §4.1–4.7 is drawn, in widget pixels (before presentation mode's scale).
constexpr double kInkMinimumPx = 2.5;

/// Samples per Catmull-Rom segment: smooth for the seed's 10 vertices, few for 200.
int samplesPerSegment(std::size_t vertices)
{
    return std::clamp(static_cast<int>(1200 / std::max<std::size_t>(vertices, 1)), 2, 12);
}

QPointF scenePoint(const Point& p) { return QPointF(p.x, p.y); }

} // namespace

void setPolylinePath(QPainterPath& path, const std::vector<Point>& points, bool close)
{
    path.clear();
    path.setFillRule(Qt::WindingFill);
    path.reserve(static_cast<int>(points.size()) + 1);
    bool started = false;
    for (const Point& pt : points) {
        if (!isFinite(pt))
            continue;
        if (started) {
            path.lineTo(pt.x, pt.y);
        } else {
            path.moveTo(pt.x, pt.y);
            started = true;
        }
    }
    if (close && started)
        path.closeSubpath();
}

FrogScenePainter::FrogScenePainter() { m_clock.start(); }

FrogScenePainter::~FrogScenePainter() = default;

void FrogScenePainter::setScale(double scale)
{
    m_scale = scale;
    m_art.setLineScale(scale);
}

void FrogScenePainter::setBezierOutline(BezierOutline mode)
{
    m_bezier = mode;
    m_fitNsSum = 0;
    m_fits = 0;
    m_fitShownUs = 0;
}

void FrogScenePainter::restart()
{
    m_fitter.reset();
    m_fitNsSum = 0;
    m_fits = 0;
    m_fitShownUs = 0;
    m_backgroundSize = QSize(); // the frame may have another size
}

void FrogScenePainter::averageFitCost()
{
    if (m_fits > 0) {
        m_fitShownUs = m_fitNsSum / m_fits / 1e3;
        m_fitNsSum = 0;
        m_fits = 0;
    }
}

void FrogScenePainter::drawBackground(QPainter& p, const QRectF& r, double W, double H, double dpr)
{
    // The background: cached as a pixmap on screen, painted as vectors in every export.
    if (dpr > 0) {
        const QSize px(std::max(1, int(std::ceil(r.width() * dpr))), std::max(1, int(std::ceil(r.height() * dpr))));
        if (px != m_backgroundSize) {
            m_background = QPixmap(px);
            m_background.setDevicePixelRatio(dpr);
            QPainter bp(&m_background);
            bp.setRenderHint(QPainter::Antialiasing, true);
            bp.scale(px.width() / dpr / W, px.height() / dpr / H);
            m_art.paintBackground(bp, W, H);
            m_backgroundSize = px;
        }
        p.drawPixmap(r, m_background, QRectF(QPointF(0, 0), QSizeF(m_background.size())));
    } else {
        p.save();
        p.translate(r.topLeft());
        p.scale(r.width() / W, r.height() / H);
        m_art.paintBackground(p, W, H);
        p.restore();
    }
}

void FrogScenePainter::draw(QPainter& p, const Simulation& sim, const QRectF& r, double dpr, std::optional<Point> look)
{
    const SceneSpec& scene = sim.scene();
    const double W = scene.params.width, H = scene.params.height;
    drawBackground(p, r, W, H, dpr);
    p.save();
    p.translate(r.topLeft());
    const double s = r.width() / W;
    p.scale(s, s);
    const double pixel = 1 / s; // one widget pixel in scene pixels
    if (scene.has(SceneComponent::Obstacles))
        drawObstacles(p, sim);
    if (scene.model == SceneModel::Pendulum) {
        drawPendulum(p, sim);
        p.restore();
        return;
    }
    // Annex II, Granota.dibuixar: back legs, body, front legs, head.
    const bool frog = scene.model == SceneModel::Frog && sim.chainCount() >= 4;
    if (frog) {
        drawLeg(p, sim, 2);
        drawLeg(p, sim, 3);
    }
    for (int i = 0; i < sim.bodyCount(); ++i)
        drawBody(p, sim, i, pixel, look);
    if (frog) {
        drawLeg(p, sim, 0);
        drawLeg(p, sim, 1);
    }
    if (scene.model == SceneModel::Frog && scene.has(SceneComponent::Head) && sim.bodyCount() > 0) {
        sim.bodyVertices(0, m_vertices);
        drawHead(p, sim, 0, look);
    }
    p.restore();
}

void FrogScenePainter::drawHead(QPainter& p, const Simulation& sim, int body, std::optional<Point> look)
{
    const std::size_t n = m_vertices.size();
    if (n < 3 || !isFinite(m_vertices[0]) || !isFinite(m_vertices[1]) || !isFinite(m_vertices[n - 1]))
        return;
    // The seed draws the head as Annex II does: upright, its 138 × 93 box at vertex 0 − (69, 46)
    // (head_pose.h). The stable solver keeps Granota's head, turned with the body.
    const HeadPose pose = sim.solver() == SolverKind::Seed ? annexIIHeadPose(m_vertices) : turningHeadPose(m_vertices);
    double target = sim.bodyTargetArea(body);
    if (!(target > 0))
        target = sim.bodyArea(body);
    const double scale = std::clamp(std::sqrt(std::max(target, 0.0) / kSeedTargetArea), 0.12, 3.0);
    const QPointF at = scenePoint(pose.centre);
    const QPointF eyes = look ? scenePoint(*look) : at + QPointF(0, 200);
    m_art.paintHead(p, at, pose.angle, scale, eyes);
}

void FrogScenePainter::paintHead(QPainter& p, const Simulation& sim, int body, std::optional<Point> look)
{
    if (body < 0 || body >= sim.bodyCount())
        return;
    sim.bodyVertices(body, m_vertices);
    drawHead(p, sim, body, look);
}

HeadPose FrogScenePainter::headPose(const Simulation& sim, int body)
{
    sim.bodyVertices(body, m_work);
    return sim.solver() == SolverKind::Seed ? annexIIHeadPose(m_work) : turningHeadPose(m_work);
}

const std::vector<Point>& FrogScenePainter::bodyOutline(const Simulation& sim, int body)
{
    const SceneSpec& scene = sim.scene();
    sim.bodyVertices(body, m_vertices);
    const std::size_t n = m_vertices.size();
    if (scene.has(SceneComponent::OutlineBezier) && m_bezier == BezierOutline::Fit && n >= 3) {
        // §4.9, the abandoned option: every frame, the least-squares Bézier curve through the
        // closed outline (M⁺ computed once per vertex count), then sampled by De Casteljau.
        const int degree = std::clamp(scene.bezierFitDegree, 1, static_cast<int>(n));
        if (!m_fitter || m_fitter->vertexCount() != static_cast<int>(n) || m_fitter->degree() != degree)
            m_fitter = std::make_unique<OutlineFitter>(static_cast<int>(n), degree);
        const qint64 t0 = m_clock.nsecsElapsed();
        m_fitter->fit(m_vertices, m_fitControl);
        sampleBezierCurve(m_fitControl, kFitSamples, m_work, m_fitCurve);
        m_fitNsSum += double(m_clock.nsecsElapsed() - t0);
        ++m_fits;
        return m_fitCurve;
    }
    if (scene.has(SceneComponent::OutlineCatmullRom) && n >= 3) {
        // The seed's curveVertex outline (Annex II, Poligon.dibuixar) for §4.12 and the frog;
        // the future work of §5.2 draws the smooth closed curve of Def 2.10.
        const int samples = samplesPerSegment(n);
        if (scene.model == SceneModel::Frog || scene.section == "4.12")
            sampleSeedBodyOutline(m_vertices, samples, m_outline);
        else
            sampleClosedCatmullRomOutline(m_vertices, samples, 0.5, m_outline);
        return m_outline;
    }
    return m_vertices; // §4.1–4.8 and the precomputed Bézier points: the polygon itself
}

void FrogScenePainter::drawBody(QPainter& p, const Simulation& sim, int body, double pixel, std::optional<Point> look)
{
    const SceneSpec& scene = sim.scene();
    const std::vector<Point>& outline = bodyOutline(sim, body);
    if (m_vertices.size() < 2)
        return;
    setPolylinePath(m_path, outline, true);
    if (scene.has(SceneComponent::Fill)) {
        p.setBrush(m_art.skin(body));
        p.setPen(m_art.bodyPen());
    } else {
        p.setBrush(Qt::NoBrush);
        // §4.1–4.7's bare polygon: never thinner than kInkMinimumPx on screen (its 3 scene px
        // were 1 px on a small canvas, too faint for a projector), thicker in presentation mode.
        QPen ink = m_art.inkPen();
        ink.setWidthF(std::max(ink.widthF(), kInkMinimumPx * m_scale * pixel));
        p.setPen(ink);
    }
    p.drawPath(m_path);
    if (scene.has(SceneComponent::Head) && scene.model != SceneModel::Frog)
        drawHead(p, sim, body, look);
}

void FrogScenePainter::drawLeg(QPainter& p, const Simulation& sim, int chain)
{
    sim.chainJoints(chain, m_joints);
    if (m_joints.size() < 3)
        return;
    const Point &m = m_joints[0], &e = m_joints[1], &w = m_joints[2];
    if (!isFinite(m) || !isFinite(e) || !isFinite(w))
        return;
    const Point bone = w - e;
    const double footAngle = norm(bone) > 1e-9 ? std::atan2(bone.y, bone.x) : kPi / 2;
    m_art.paintFoot(p, scenePoint(w), footAngle, chain < 2 ? 0.8 : 1.0);
    sampleLegOutline(m, e, w, kLegHalfWidth, 6, m_outline); // Annex II, Pota.dibuixar: factor = 7
    setPolylinePath(m_path, m_outline, true);
    p.setBrush(m_art.skin(0));
    p.setPen(m_art.legPen());
    p.drawPath(m_path);
}

void FrogScenePainter::drawPendulum(QPainter& p, const Simulation& sim)
{
    for (int c = 0; c < sim.chainCount(); ++c) {
        sim.chainJoints(c, m_joints);
        if (m_joints.empty())
            continue;
        setPolylinePath(m_path, m_joints, false);
        p.setBrush(Qt::NoBrush);
        p.setPen(m_art.rodPen());
        p.drawPath(m_path);
        p.setPen(m_art.jointPen());
        for (std::size_t k = 1; k < m_joints.size(); ++k) {
            if (!isFinite(m_joints[k]))
                continue;
            p.setBrush(m_art.jointBrush());
            p.drawEllipse(scenePoint(m_joints[k]), 10 * m_scale, 10 * m_scale);
        }
        if (isFinite(m_joints[0])) { // the clau the pendulum hangs from (§4.14)
            p.setBrush(m_art.pinBrush());
            p.drawEllipse(scenePoint(m_joints[0]), 8 * m_scale, 8 * m_scale);
            p.setBrush(m_art.whiteBrush());
            p.setPen(Qt::NoPen);
            p.drawEllipse(scenePoint(m_joints[0]), 3 * m_scale, 3 * m_scale);
        }
    }
}

void FrogScenePainter::drawObstacles(QPainter& p, const Simulation& sim)
{
    for (const ObstacleSpec& o : sim.obstacles()) {
        setPolylinePath(m_path, o.points, o.closed);
        if (o.closed) {
            p.setBrush(m_art.stoneBrush());
            p.setPen(m_art.stonePen());
            p.drawPath(m_path);
        } else {
            p.setBrush(Qt::NoBrush);
            p.setPen(m_art.logPen());
            p.drawPath(m_path);
            p.setPen(m_art.logHighlightPen());
            p.drawPath(m_path);
        }
    }
}

} // namespace granota::ui
