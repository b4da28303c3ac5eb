#include "ui/frog/frog_overlay_painter.h"

#include "core/base/aabb.h"
#include "core/base/math_constants.h"
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/seed_angle.h"
#include "ui/common/number_text.h"
#include "ui/common/segment_clip.h"
#include "ui/frog/frog_art.h"
#include "ui/frog/frog_run.h"
#include "ui/frog/frog_scene_painter.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// Velocity arrows: the step's displacement drawn this many times longer.
constexpr double kVelocityScale = 4;
/// How much of the trail is drawn at most: this many times the frame's width plus height.
constexpr double kTrailInkBudget = 20;
const QColor kEdgeColour(0xff, 0x8a, 0x1e);
const QColor kVelocityColour(0x1f, 0x5f, 0xd8);
const QColor kGhostColour(0x5a, 0x2d, 0x82);
const QColor kTrailColour(0xe0, 0x6c, 0x00);
const QColor kPairColour(0xc2, 0x18, 0x5b);
const QColor kProtractorColour(0x1e, 0x5a, 0x9c);
const QColor kMarkedBodyColour(0xd8, 0x1b, 0x60); // the body the plots show alone
const QColor kAtLimitColour(0xc6, 0x28, 0x28);
const QColor kRulerColour(0x21, 0x21, 0x21);

QPointF overlayPoint(const Point& p) { return QPointF(p.x, p.y); }

} // namespace

FrogOverlayPainter::FrogOverlayPainter() { setStyle(1, QFont(), QFont()); }

void FrogOverlayPainter::setStyle(double k, const QFont& labelFont, const QFont& widgetFont)
{
    m_scale = k;
    m_edgePen = QPen(kEdgeColour, 2 * k);
    m_edgePen.setCosmetic(true);
    m_velocityPen = QPen(kVelocityColour, 2 * k, Qt::SolidLine, Qt::RoundCap);
    m_velocityPen.setCosmetic(true);
    m_ringPen = QPen(QColor(0x1c, 0x2a, 0x33), 1.2 * k);
    m_ringPen.setCosmetic(true);
    m_numberPen = QPen(QColor(0x10, 0x18, 0x1c));
    m_markPen = QPen(Qt::white, 2 * k);
    m_panelBrush = QBrush(QColor(0x10, 0x1c, 0x22, 170));
    m_trackBrush = QBrush(QColor(255, 255, 255, 50));
    m_goodBrush = QBrush(QColor(0x6c, 0xc2, 0x4a));
    m_offBrush = QBrush(QColor(0xf0, 0xa2, 0x3a));
    m_jointDotBrush = QBrush(QColor(0xff, 0xe0, 0x8a));
    m_font = labelFont;
    m_numberFont = widgetFont;
    m_numberFont.setPixelSize(std::max(1, int(std::lround(11 * k))));
}

void FrogOverlayPainter::draw(QPainter& p, const Frame& f, const QRectF& r, const QRectF& target)
{
    const Simulation& sim = *f.run.simulation();
    const SceneSpec& scene = sim.scene();
    p.save();
    p.translate(r.topLeft());
    const double s = r.width() / scene.params.width;
    p.scale(s, s);
    const double pixel = 1 / s; // one widget pixel in scene pixels
    if (scene.model != SceneModel::Pendulum)
        drawMarkedBody(p, sim, f.markedBody, pixel);
    if (const Simulation* ghost = f.run.ghost())
        drawGhost(p, *ghost);
    if (f.overlays.trail)
        drawTrail(p, sim, f.run);
    if (f.overlays.pairs)
        drawPairs(p, sim);
    drawPoints(p, f, sim, pixel);
    if (f.overlays.protractor)
        drawProtractor(p, sim, pixel);
    if (f.ruler)
        drawRuler(p, f, pixel);
    p.restore();
    // The text panel may run below a small scene (presentation mode on a narrow canvas): it
    // is clipped to the canvas, not to the scene.
    if (f.textPanel) {
        p.save();
        p.setClipRect(target);
        drawTextPanel(p, f, sim, r);
        p.restore();
    }
}

void FrogOverlayPainter::drawMarkedBody(QPainter& p, const Simulation& sim, int body, double pixel)
{
    if (body < 0 || body >= sim.bodyCount())
        return;
    sim.bodyVertices(body, m_work);
    if (m_work.size() < 3 || !std::all_of(m_work.begin(), m_work.end(), [](Point v) { return isFinite(v); }))
        return;
    const Aabb box = boundingBox(m_work.data(), int(m_work.size()));
    // Sizes in screen px (`pixel`: scene px per screen px), so the mark reads at any zoom.
    const double k = m_scale, grow = 6 * k * pixel;
    const QRectF around(QPointF(box.minX - grow, box.minY - grow), QPointF(box.maxX + grow, box.maxY + grow));
    p.save();
    QPen pen(kMarkedBodyColour, 2.5 * k, Qt::DashLine);
    pen.setCosmetic(true);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawRoundedRect(around, grow, grow);
    // Its number, as the plots' list names it, above the box (below it at the frame's top).
    QFont font = p.font();
    font.setBold(true);
    font.setPixelSize(std::max(1, int(std::lround(15 * k * pixel))));
    p.setFont(font);
    const QString label = QString::number(body + 1);
    const QFontMetricsF metrics(font);
    const QSizeF size(metrics.horizontalAdvance(label) + 8 * k * pixel, metrics.height() + 2 * k * pixel);
    const double top = around.top() - size.height() >= 0 ? around.top() - size.height() : around.bottom();
    const QRectF tag(QPointF(around.center().x() - size.width() / 2, top), size);
    p.setPen(Qt::NoPen);
    p.setBrush(kMarkedBodyColour);
    p.drawRoundedRect(tag, 3 * k * pixel, 3 * k * pixel);
    p.setPen(Qt::white);
    p.drawText(tag, Qt::AlignCenter, label);
    p.restore();
}

void FrogOverlayPainter::drawGhost(QPainter& p, const Simulation& g)
{
    // The other solver's bodies and chains, pale and dashed over this one's: where they part
    // is what the two solvers do differently with the same input.
    QPen pen(kGhostColour, 2.5 * m_scale, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin);
    pen.setCosmetic(true);
    p.save();
    p.setPen(pen);
    p.setBrush(QColor(255, 255, 255, 70));
    for (int i = 0; i < g.bodyCount(); ++i) {
        g.bodyVertices(i, m_work);
        setPolylinePath(m_path, m_work, true);
        p.drawPath(m_path);
    }
    p.setBrush(Qt::NoBrush);
    for (int c = 0; c < g.chainCount(); ++c) {
        g.chainJoints(c, m_work);
        setPolylinePath(m_path, m_work, false);
        p.drawPath(m_path);
    }
    p.restore();
}

void FrogOverlayPainter::drawTrail(QPainter& p, const Simulation& sim, const FrogRun& run)
{
    m_trailSegmentsDrawn = 0;
    const std::deque<Point>& trail = run.trail();
    if (trail.size() < 2)
        return;
    // Square caps: Qt strokes a thick round cap as a curve, a hundred times slower.
    QPen pen(kTrailColour, 2 * m_scale, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin);
    pen.setCosmetic(true);
    // Only what the frame shows (the canvas clips to it), each segment cut to it and stroked
    // on its own: a blown-up seed's trail crosses the frame hundreds of times, and stroking it
    // as one path with round joins and caps (its outline overlapping itself everywhere) took
    // Qt 4.7 s a frame (tests/benchmarks/bench_gui.cpp, BM_GuiSeedExplodedTrail).
    const SceneSpec& scene = sim.scene();
    const double margin = 0.05 * std::max(scene.params.width, scene.params.height);
    const QRectF frame = QRectF(0, 0, scene.params.width, scene.params.height).adjusted(-margin, -margin, margin, margin);
    // The newest first, up to kTrailInkBudget frames' worth of line: a trail that sweeps the
    // frame back and forth every step (a blown-up body) is noise past that, and each sweep
    // costs a frame's width of stroking; an ordinary trail stays far below it.
    const double budget = kTrailInkBudget * (scene.params.width + scene.params.height);
    double ink = 0;
    m_trailLines.clear();
    for (std::size_t i = trail.size() - 1; i >= 1 && ink < budget; --i)
        if (const auto part = clipSegment(trail[i - 1], trail[i], frame)) {
            m_trailLines.emplace_back(part->first.x, part->first.y, part->second.x, part->second.y);
            ink += m_trailLines.back().length();
        }
    m_trailSegmentsDrawn = int(m_trailLines.size());
    p.save();
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawLines(m_trailLines.data(), int(m_trailLines.size()));
    p.restore();
}

void FrogOverlayPainter::drawPairs(QPainter& p, const Simulation& sim)
{
    sim.broadPhasePairs(m_pairs);
    if (m_pairs.empty())
        return;
    // Thick enough for a projector (they were 1.2 px): widget pixels, scaled in presentation mode.
    QPen box(kPairColour, 2.5 * m_scale, Qt::DashLine);
    box.setCosmetic(true);
    QPen link(kPairColour, 3 * m_scale);
    link.setCosmetic(true);
    p.save();
    p.setBrush(Qt::NoBrush);
    const auto boxAndCentre = [this, &sim](int body) {
        sim.bodyVertices(body, m_work);
        const Aabb b = boundingBox(m_work.data(), int(m_work.size()));
        return std::pair{QRectF(QPointF(b.minX, b.minY), QPointF(b.maxX, b.maxY)),
                         Point(0.5 * (b.minX + b.maxX), 0.5 * (b.minY + b.maxY))};
    };
    for (const auto& [a, b] : m_pairs) {
        const auto [boxA, centreA] = boxAndCentre(a);
        const auto [boxB, centreB] = boxAndCentre(b);
        p.setPen(box);
        p.drawRect(boxA);
        p.drawRect(boxB);
        p.setPen(link);
        p.drawLine(QPointF(centreA.x, centreA.y), QPointF(centreB.x, centreB.y));
    }
    p.restore();
}

void FrogOverlayPainter::drawPoints(QPainter& p, const Frame& f, const Simulation& sim, double pixel)
{
    const Overlays& o = f.overlays;
    if (!o.vertices && !o.springs && !o.velocities)
        return;
    const double k = m_scale;
    const double dot = 3.5 * k * pixel;
    const auto drawSprings = [&](const std::vector<Point>& pts, bool closed) {
        if (o.springs) {
            setPolylinePath(m_path, pts, closed);
            p.setBrush(Qt::NoBrush);
            p.setPen(m_edgePen);
            p.drawPath(m_path);
        }
    };
    const std::vector<std::size_t>& offset = f.run.previousOffset();
    for (int i = 0; i < sim.bodyCount(); ++i) {
        sim.bodyVertices(i, m_vertices);
        drawSprings(m_vertices, true);
        if (o.velocities && f.run.previousValid() && std::size_t(i) + 1 < offset.size() &&
            offset[std::size_t(i) + 1] - offset[std::size_t(i)] == m_vertices.size()) {
            p.setPen(m_velocityPen);
            const Point* prev = f.run.previous().data() + offset[std::size_t(i)];
            for (std::size_t v = 0; v < m_vertices.size(); ++v) {
                const Point tip = m_vertices[v] + kVelocityScale * (m_vertices[v] - prev[v]);
                if (isFinite(tip) && isFinite(m_vertices[v]))
                    p.drawLine(overlayPoint(m_vertices[v]), overlayPoint(tip));
            }
        }
        if (o.vertices) {
            p.setPen(m_ringPen);
            p.setBrush(f.art.whiteBrush());
            for (const Point& v : m_vertices)
                if (isFinite(v))
                    p.drawEllipse(overlayPoint(v), dot, dot);
            if (m_vertices.size() <= 40) { // numbered as in Annex II's arrays, v_0 first
                while (m_numbers.size() < m_vertices.size())
                    m_numbers.push_back(QString::number(m_numbers.size()));
                p.setPen(m_numberPen);
                p.save();
                const QTransform world = p.worldTransform();
                p.resetTransform();
                p.setFont(m_numberFont);
                for (std::size_t v = 0; v < m_vertices.size(); ++v)
                    if (isFinite(m_vertices[v]))
                        p.drawText(world.map(overlayPoint(m_vertices[v])) + QPointF(5 * k, -5 * k), m_numbers[v]);
                p.restore();
            }
        }
    }
    for (int c = 0; c < sim.chainCount(); ++c) {
        sim.chainJoints(c, m_joints);
        drawSprings(m_joints, false);
        if (o.vertices) {
            p.setPen(m_ringPen);
            p.setBrush(m_jointDotBrush);
            for (const Point& v : m_joints)
                if (isFinite(v))
                    p.drawEllipse(overlayPoint(v), dot, dot);
        }
    }
}

void FrogOverlayPainter::drawProtractor(QPainter& p, const Simulation& sim, double pixel)
{
    // At each limited joint: the range its limits allow, shaded, and the link's angle in
    // degrees beyond its tip, red when the joint is held at a limit (§4.15). On a small
    // canvas a label that would cover another is left out, those at a limit first kept.
    const double k = m_scale;
    const QTransform world = p.worldTransform();
    std::vector<ProtractorLabel>& labels = m_protractorLabels; // capacities reused frame to frame
    labels.clear();
    for (int c = 0; c < sim.chainCount(); ++c) {
        readLinkAngles(sim, c, m_joints, m_angles);
        for (std::size_t l = 0; l < m_angles.size(); ++l) {
            const LinkAngleReading& a = m_angles[l];
            if (!a.limit)
                continue;
            const Point at = m_joints[l];
            const Point d = m_joints[l + 1] - at;
            const double length = std::sqrt(d.x * d.x + d.y * d.y);
            const double radius = std::max(0.6 * length, 8 * k * pixel);
            const double span = a.limit->max - a.limit->min;
            const int n = std::max(4, int(std::ceil(span / (kPi / 36))));
            QPolygonF sector;
            sector << overlayPoint(at);
            for (int i = 0; i <= n; ++i)
                sector << overlayPoint(at + radius * seedDirection(a.reference + a.limit->min + span * i / n));
            const QColor colour = a.atLimit ? kAtLimitColour : kProtractorColour;
            QColor fill = colour;
            fill.setAlpha(40);
            QPen edge(colour, 1.2 * k);
            edge.setCosmetic(true);
            p.setPen(edge);
            p.setBrush(fill);
            p.drawPolygon(sector);
            const double degrees = std::round(a.angle * 180 / kPi) + 0.0; // + 0.0: a −0 reads 0
            labels.push_back({world.map(overlayPoint(at + (radius + 12 * k * pixel) * seedDirection(a.reference + a.angle))),
                              displayFixed(degrees, 0) + QStringLiteral("°"), a.atLimit});
        }
    }
    std::stable_partition(labels.begin(), labels.end(), [](const ProtractorLabel& l) { return l.atLimit; });
    p.save();
    p.resetTransform();
    p.setFont(m_numberFont);
    const QFontMetricsF fm(m_numberFont);
    std::vector<QRectF>& drawn = m_protractorBoxes;
    drawn.clear();
    for (const ProtractorLabel& l : labels) {
        QRectF box(0, 0, fm.horizontalAdvance(l.text) + 6 * k, fm.height() + 2 * k);
        box.moveCenter(l.at);
        if (std::any_of(drawn.begin(), drawn.end(), [&box](const QRectF& r) { return r.intersects(box); }))
            continue;
        drawn.push_back(box);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 210));
        p.drawRoundedRect(box, 3 * k, 3 * k);
        p.setPen(l.atLimit ? kAtLimitColour : kProtractorColour);
        p.drawText(box, Qt::AlignCenter, l.text);
    }
    p.restore();
}

void FrogOverlayPainter::drawRuler(QPainter& p, const Frame& f, double pixel)
{
    const double k = m_scale;
    const Point a = f.ruler->first, b = f.ruler->second;
    const Point d = b - a;
    const double length = std::sqrt(d.x * d.x + d.y * d.y);
    const Point across = length > 0 ? Point(-d.y / length, d.x / length) : Point(0, 1);
    const double tick = 7 * k * pixel;
    p.save();
    for (const auto& [colour, width] : {std::pair{QColor(Qt::white), 4.0 * k}, std::pair{kRulerColour, 1.6 * k}}) {
        QPen pen(colour, width, Qt::SolidLine, Qt::FlatCap);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.drawLine(overlayPoint(a), overlayPoint(b));
        for (const Point& end : {a, b})
            p.drawLine(overlayPoint(end - tick * across), overlayPoint(end + tick * across));
    }
    // The length, beside the middle, on a pale box, kept inside the canvas.
    const QTransform world = p.worldTransform();
    p.resetTransform();
    p.setFont(m_numberFont);
    const QFontMetricsF fm(m_numberFont);
    QRectF box(0, 0, fm.horizontalAdvance(f.rulerText) + 8 * k, fm.height() + 4 * k);
    box.moveCenter(world.map(overlayPoint(0.5 * (a + b) + (2.2 * tick) * across)));
    box.moveLeft(std::clamp(box.left(), 0.0, std::max(0.0, f.bounds.width() - box.width())));
    box.moveTop(std::clamp(box.top(), 0.0, std::max(0.0, f.bounds.height() - box.height())));
    p.setPen(QPen(kRulerColour, 1));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRoundedRect(box, 3 * k, 3 * k);
    p.drawText(box, Qt::AlignCenter, f.rulerText);
    p.restore();
}

void FrogOverlayPainter::setLines(const QStringList& lines, double room, bool wrapFirst)
{
    m_lines.resize(static_cast<std::size_t>(lines.size()));
    for (int i = 0; i < lines.size(); ++i) {
        QStaticText& t = m_lines[static_cast<std::size_t>(i)];
        t.setTextFormat(Qt::PlainText);
        t.setText(lines[i]);
        t.setTextWidth(i == 0 && wrapFirst ? room : -1);
        t.prepare(QTransform(), m_font);
        // A line wider than the canvas leaves (large text in presentation mode, a narrow
        // window) wraps at its spaces instead of running off the canvas.
        if (t.size().width() > room) {
            t.setTextWidth(room);
            t.prepare(QTransform(), m_font);
        }
    }
}

QStringList FrogOverlayPainter::lines() const
{
    QStringList lines;
    for (const QStaticText& t : m_lines)
        lines << t.text();
    return lines;
}

double FrogOverlayPainter::linesWidth() const
{
    double width = 0;
    for (const QStaticText& t : m_lines)
        width = std::max(width, t.size().width());
    return width;
}

void FrogOverlayPainter::drawTextPanel(QPainter& p, const Frame& f, const Simulation& sim, const QRectF& sceneRect)
{
    const bool bar = f.overlays.area && sim.bodyCount() > 0;
    if (m_lines.empty() && !bar)
        return;
    const double k = m_scale, margin = kPanelMargin * k, pad = kPanelPad * k;
    double width = 0, height = 0;
    for (const QStaticText& t : m_lines) {
        width = std::max(width, t.size().width());
        height += t.size().height();
    }
    const double barHeight = bar ? 10 * k : 0, barWidth = 220 * k;
    if (bar) {
        width = std::max(width, barWidth);
        height += barHeight + pad;
    }
    const QRectF box(sceneRect.left() + margin, sceneRect.top() + margin, width + 2 * pad, height + 2 * pad);
    p.setPen(Qt::NoPen);
    p.setBrush(m_panelBrush);
    p.drawRoundedRect(box, 6 * k, 6 * k);
    p.setPen(QColor(0xf6, 0xf7, 0xf2));
    p.setFont(m_font);
    double y = box.top() + pad;
    for (const QStaticText& t : m_lines) {
        p.drawStaticText(QPointF(box.left() + pad, y), t);
        y += t.size().height();
    }
    if (bar) { // area against target (§4.5): the bar spans 0 … 2 A₀, the mark is A₀
        const double area = sim.bodyArea(0), target = sim.bodyTargetArea(0);
        const double share = target > 0 && std::isfinite(area) ? std::clamp(area / (2 * target), 0.0, 1.0) : 0.0;
        const QRectF track(box.left() + pad, y + pad, barWidth, barHeight);
        p.setBrush(m_trackBrush);
        p.drawRect(track);
        p.setBrush(std::abs(share - 0.5) < 0.05 ? m_goodBrush : m_offBrush);
        p.drawRect(QRectF(track.left(), track.top(), track.width() * share, track.height()));
        p.setPen(m_markPen);
        p.drawLine(QPointF(track.center().x(), track.top() - 2 * k), QPointF(track.center().x(), track.bottom() + 2 * k));
    }
}

} // namespace granota::ui
