#include "ui/frog/frog_tab.h"

#include "core/base/math_constants.h"
#include "core/softbody/outline.h"
#include "ui/common/path_recorder.h"
#include "ui/frog/frog_canvas.h"
#include "ui/files/exporter.h"
#include "ui/files/tikz_writer.h"

#include <QDir>
#include <QImage>
#include <QPainter>
#include <QPushButton>
#include <QTextStream>

#include <algorithm>
#include <cmath>


/// \file frog_tab_exports.cpp
/// FrogTab, part: what File ▸ Export writes of the run: the CSV of the vertices and joints, the
/// TikZ picture (the head recorded as paths) and the numbered frames of a video.

namespace granota::ui {

namespace {

/// Flips Processing's y (down) for TikZ (up).
std::vector<Point> flippedForTikz(const std::vector<Point>& points, double height)
{
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Point& p : points)
        out.emplace_back(p.x, height - p.y);
    return out;
}

} // namespace

QString FrogTab::csv() const
{
    QString out;
    QTextStream s(&out);
    const Simulation* sim = m_run->simulation();
    s << "# scene " << QString::fromStdString(scene().name) << " (" << QString::fromStdString(scene().section) << "), solver "
      << QString::fromStdString(solverName(m_run->solver())) << ", step " << (sim ? sim->stepCount() : 0) << "\n";
    s << "kind,index,point,x,y\n";
    if (!sim)
        return out;
    std::vector<Point> pts;
    const auto write = [&](const char* kind, int index) {
        for (std::size_t k = 0; k < pts.size(); ++k)
            s << kind << ',' << index << ',' << k << ',' << QString::number(pts[k].x, 'g', 12) << ','
              << QString::number(pts[k].y, 'g', 12) << '\n';
    };
    for (int i = 0; i < sim->bodyCount(); ++i) {
        sim->bodyVertices(i, pts);
        write("body", i);
    }
    for (int c = 0; c < sim->chainCount(); ++c) {
        sim->chainJoints(c, pts);
        write("chain", c);
    }
    return out;
}

void FrogTab::drawTikz(TikzWriter& w) const
{
    const Simulation* sim = m_run->simulation();
    if (!sim)
        return;
    const double H = scene().params.height;
    w.comment(QStringLiteral("Granota: scene %1 (%2), solver %3, step %4")
                  .arg(QString::fromStdString(scene().name), QString::fromStdString(scene().section),
                       QString::fromStdString(solverName(m_run->solver())))
                  .arg(sim->stepCount()));
    // The frame, so that the picture keeps the scene's proportions; what is drawn is clipped
    // to it, as the canvas clips to the scene (a foot past the floor is not drawn).
    const double W = scene().params.width;
    w.polyline({{0, 0}, {W, 0}, {W, H}, {0, H}}, QColor(0x9a, 0x9a, 0x9a), 0.4, false, true);
    w.clipTo({0, 0}, {W, H});
    // As FrogCanvas::drawScene paints them: filled stones and bodies, legs with their feet.
    const FrogArt& art = m_canvas->art();
    for (const ObstacleSpec& o : sim->obstacles()) {
        if (o.closed)
            w.polygon(flippedForTikz(o.points, H), art.stonePen().color(), FrogArt::stoneColour(), 0.8);
        else
            w.polyline(flippedForTikz(o.points, H), art.logPen().color(), 3.0);
    }
    std::vector<Point> pts;
    const auto path = [H](const QPolygonF& polygon) {
        std::vector<Point> out;
        for (const QPointF& q : polygon)
            out.emplace_back(q.x(), H - q.y());
        return out;
    };
    const auto leg = [&](int c) {
        sim->chainJoints(c, pts);
        if (pts.size() < 3 || !isFinite(pts[0]) || !isFinite(pts[1]) || !isFinite(pts[2]))
            return;
        // FrogCanvas::drawLeg: the foot at the wrist along the lower bone, then the leg over it.
        const Point bone = pts[2] - pts[1];
        const double angle = norm(bone) > 1e-9 ? std::atan2(bone.y, bone.x) : kPi / 2;
        const QPointF wrist(pts[2].x, pts[2].y);
        const double scale = c < 2 ? 0.8 : 1.0;
        for (const QPolygonF& line : art.footWeb(wrist, angle, scale).toSubpathPolygons()) {
            w.polyline(path(line), art.footEdgePen().color(), 1.4);
            w.polyline(path(line), art.footWebPen().color(), 0.8);
        }
        for (const QPolygonF& toe : art.footToes(wrist, angle, scale).toFillPolygons())
            w.polygon(path(toe), art.footEdgePen().color(), art.toeColour(), 0.3);
        w.polygon(flippedForTikz(legOutline(pts[0], pts[1], pts[2], FrogCanvas::kLegHalfWidth, 6), H), art.legPen().color(),
                  FrogArt::skinColour(0), 0.6);
    };
    const bool frog = scene().model == SceneModel::Frog && sim->chainCount() >= 4;
    if (frog) {
        leg(2);
        leg(3);
    }
    const bool filled = scene().has(SceneComponent::Fill);
    for (int i = 0; i < sim->bodyCount(); ++i) {
        const std::vector<Point> outline = flippedForTikz(m_canvas->bodyOutline(i), H);
        if (filled)
            w.polygon(outline, art.bodyPen().color(), FrogArt::skinColour(i), 0.8);
        else
            w.polyline(outline, art.inkPen().color(), 0.7, false, true);
    }
    if (frog) {
        leg(0);
        leg(1);
    }
    if (scene().model == SceneModel::Frog && scene().has(SceneComponent::Head) && sim->bodyCount() > 0)
        drawTikzHead(w);
    if (scene().model == SceneModel::Pendulum)
        for (int c = 0; c < sim->chainCount(); ++c) {
            sim->chainJoints(c, pts);
            w.polyline(flippedForTikz(pts, H), QColor(0x37, 0x47, 0x4f), 1.5);
            for (const Point& p : pts)
                w.point(Point(p.x, H - p.y), QColor(0xf2, 0xb1, 0x34));
        }
}

void FrogTab::drawTikzHead(TikzWriter& w) const
{
    // The head as the canvas paints it over the body (FrogCanvas::drawScene), recorded as
    // paths (as Figs 4.11 and 4.12 are): each filled outline filled, each line drawn.
    const double H = scene().params.height;
    PathRecorder recorder(QSize(int(std::ceil(scene().params.width)), int(std::ceil(H))));
    {
        QPainter p(&recorder);
        m_canvas->paintHeadOf(p, 0);
    }
    w.comment(QStringLiteral("the head"));
    const auto opaque = [](const QColor& c) { return c.isValid() ? QColor(c.red(), c.green(), c.blue()) : QColor(); };
    for (const PathRecorder::Shape& shape : recorder.shapes()) {
        // Scene px to the picture's pt, as the body's 4 px pen is drawn 0.8 pt above.
        const double width = std::max(0.2, shape.strokeWidth * 0.2);
        for (const QPolygonF& polygon : shape.path.toSubpathPolygons()) {
            if (polygon.size() < 2)
                continue;
            std::vector<Point> points;
            for (const QPointF& q : polygon)
                points.emplace_back(q.x(), H - q.y());
            if (shape.fill.isValid() && polygon.size() > 2)
                w.polygon(points, opaque(shape.stroke), opaque(shape.fill), width);
            else if (shape.stroke.isValid())
                w.polyline(points, opaque(shape.stroke), width, false, polygon.isClosed());
        }
    }
}

long FrogTab::shownStep() const
{
    const Simulation* sim = m_run->simulation();
    return sim ? sim->stepCount() : 0;
}

QString FrogTab::exportFrames(const QString& directory, int frames, QSize size, long firstStep)
{
    if (frames < 1)
        return tr("The number of frames must be at least 1.");
    if (directory.isEmpty() || (!QDir(directory).exists() && !QDir().mkpath(directory)))
        return tr("Cannot create the folder “%1”.").arg(directory);
    if (!m_run->simulation())
        return tr("There is no scene to export.");
    const QDir dir(directory);
    size = QSize(size.width() / 2 * 2, size.height() / 2 * 2); // even sides: yuv420p video
    if (size.width() < 16 || size.height() < 16)
        size = kFrameSize;
    // The run pauses (its timer would step it between frames) and goes back to the step the
    // user saw; the recorded run replays from there exactly.
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    if (firstStep >= 0 && firstStep != shownStep() && !m_run->seek(firstStep))
        return tr("Step %1 is no longer recorded.").arg(firstStep);
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    for (int i = 0; i < frames; ++i) {
        image.fill(Qt::white);
        {
            QPainter p(&image);
            m_canvas->renderFrame(p, QRectF(QPointF(0, 0), QSizeF(size)));
        }
        const QString file = dir.filePath(QStringLiteral("frame_%1.png").arg(i, 4, 10, QLatin1Char('0')));
        if (const QString error = writePngFile(image, file); !error.isEmpty())
            return error;
        if (i + 1 < frames)
            m_run->step(); // the canvas's fixed step: one per frame, 60 per second
    }
    return {};
}

} // namespace granota::ui
