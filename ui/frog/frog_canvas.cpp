#include "ui/frog/frog_canvas.h"
#include "ui/common/segment_clip.h"
#include "ui/common/error_text.h"
#include "core/base/math_constants.h"
#include "ui/common/focus_frame.h"
#include "ui/common/number_text.h"
#include "ui/common/presentation_scale.h"

#include "core/softbody/outline.h"
#include "core/softbody/outline_sampling.h"
#include "core/softbody/polygon_geometry.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCursor>
#include <QEnterEvent>
#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// Samples of the per-frame least-squares Bézier curve (§4.9's abandoned option).
constexpr int kFitSamples = 160;
/// Annex II, Pota.dibuixar: `factor = 7`, the half-thickness of a leg.
constexpr double kLegFactor = FrogCanvas::kLegHalfWidth;
/// The head image's size in Annex II belongs to the frog's target area, Areal = 20000 px².
constexpr double kSeedTargetArea = 20000;
/// Velocity arrows: the step's displacement drawn this many times longer.
constexpr double kVelocityScale = 4;
/// How often the text overlays and the averaged timings refresh.
constexpr qint64 kTextRefreshNs = 250'000'000;

const QColor kLetterbox(0x26, 0x30, 0x36);
const QColor kSkyTop(0xb9, 0xdc, 0xee);                  // FrogArt's sky, top
const QColor kFrameCaptionColour(0x26, 0x30, 0x36, 190); // the frame's caption, over the sky
constexpr double kPanelMargin = 8;                       // the text panel: from the frame's corner, px (× presentation scale)
constexpr double kPanelPad = 6;                          // and inside it
const QColor kMudBottom(0x86, 0x6a, 0x44);               // FrogArt's bank, bottom
const QColor kEdgeColour(0xff, 0x8a, 0x1e);
const QColor kVelocityColour(0x1f, 0x5f, 0xd8);
const QColor kGhostColour(0x5a, 0x2d, 0x82);
const QColor kTrailColour(0xe0, 0x6c, 0x00);
const QColor kPairColour(0xc2, 0x18, 0x5b);
/// The thinnest the bare polygon of §4.1–4.7 is drawn, in widget pixels (before presentation mode's scale).
constexpr double kInkMinimumPx = 2.5;
/// How much of the trail is drawn at most: this many times the frame's width plus height.
constexpr double kTrailInkBudget = 20;
const QColor kProtractorColour(0x1e, 0x5a, 0x9c);
const QColor kMarkedBodyColour(0xd8, 0x1b, 0x60); // the body the plots show alone
const QColor kAtLimitColour(0xc6, 0x28, 0x28);
const QColor kRulerColour(0x21, 0x21, 0x21);

/// Samples per Catmull-Rom segment: smooth for the seed's 10 vertices, few for 200.
int samplesPerSegment(std::size_t vertices)
{
    return std::clamp(static_cast<int>(1200 / std::max<std::size_t>(vertices, 1)), 2, 12);
}

QPointF q(const Point& p) { return QPointF(p.x, p.y); }

} // namespace

FrogCanvas::FrogCanvas(FrogRun* run, QWidget* parent) : QWidget(parent), m_run(run)
{
    setMouseTracking(true); // Processing's mouseX/mouseY are always current (§4.1, §4.13)
    setFocusPolicy(Qt::StrongFocus);
    setDrawsOwnFocusFrame(this);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_clock.start();
    m_textClock.start();
    buildPens();
    observe();
}

FrogCanvas::FrogCanvas(QWidget* parent) : FrogCanvas(new FrogRun, parent) { m_run->setParent(this); }

void FrogCanvas::observe()
{
    connect(m_run, &FrogRun::stepped, this, [this] {
        refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::frameRan, this, [this] {
        if (m_textClock.nsecsElapsed() >= kTextRefreshNs)
            refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::changed, this, [this] {
        refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::runShown, this, &FrogCanvas::runShown);
    connect(m_run, &FrogRun::grabLost, this, &FrogCanvas::letGo);
}

FrogCanvas::~FrogCanvas() = default;

void FrogCanvas::runShown(bool fresh)
{
    m_fitter.reset();
    m_pressed = false;
    m_keyboardHeld = false;
    m_spawnHeld = false;
    m_fitNsSum = 0;
    m_fits = 0;
    m_fitShownUs = 0;
    m_backgroundSize = QSize(); // the frame may have another size
    // Processing's mouseX/mouseY hold from the first frame (§4.1, §4.13); a run brought back
    // is not sent one (recorded, it would cut off the run's recorded future).
    if (fresh && sim() && m_mouseKnown && underMouse())
        m_run->send(InputKind::Move, m_mouse);
    m_reportedRadius = -1;
    reportMouseRadius();
    unsetCursor();
    refreshTexts();
    update();
}

void FrogCanvas::letGo()
{
    m_pressed = false;
    m_keyboardHeld = false;
    m_spawnHeld = false;
    unsetCursor();
    reportMouseRadius();
}

void FrogCanvas::setOverlays(const Overlays& overlays)
{
    m_overlays = overlays;
    m_run->setGhostShown(overlays.ghost);
    m_run->setTrailShown(overlays.trail);
    m_run->setKeepsPrevious(overlays.velocities);
    refreshTexts();
    update();
}

void FrogCanvas::setBezierOutline(BezierOutline mode)
{
    m_bezier = mode;
    m_fitNsSum = 0;
    m_fits = 0;
    m_fitShownUs = 0;
    refreshTexts();
    update();
}

void FrogCanvas::setPresentation(bool on)
{
    m_style.scale = presentationScale(on);
    buildPens();
    refreshTexts();
    update();
}

void FrogCanvas::buildPens()
{
    const double k = m_style.scale;
    m_art.setLineScale(k);
    m_framePen = QPen(QColor(0x26, 0x30, 0x36, 45), 1);
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
    m_font = m_style.labelFont();
    m_numberFont = font();
    m_numberFont.setPixelSize(std::max(1, int(std::lround(11 * k))));
}

QStringList FrogCanvas::textLines() const
{
    QStringList lines;
    for (const QStaticText& t : m_lines)
        lines << t.text();
    return lines;
}

void FrogCanvas::drawPairs(QPainter& p)
{
    sim()->broadPhasePairs(m_pairs);
    if (m_pairs.empty())
        return;
    // Thick enough for a projector (they were 1.2 px): widget pixels, scaled in presentation mode.
    QPen box(kPairColour, 2.5 * m_style.scale, Qt::DashLine);
    box.setCosmetic(true);
    QPen link(kPairColour, 3 * m_style.scale);
    link.setCosmetic(true);
    p.save();
    p.setBrush(Qt::NoBrush);
    const auto boxAndCentre = [this](int body) {
        sim()->bodyVertices(body, m_work);
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

std::vector<LinkAngleReading> FrogCanvas::linkAngles(int chain) const
{
    std::vector<Point> joints;
    std::vector<LinkAngleReading> out;
    if (sim() && chain >= 0 && chain < sim()->chainCount())
        readLinkAngles(*sim(), chain, joints, out);
    return out;
}

void FrogCanvas::drawProtractor(QPainter& p, double pixel)
{
    // At each limited joint: the range its limits allow, shaded, and the link's angle in
    // degrees beyond its tip, red when the joint is held at a limit (§4.15). On a small
    // canvas a label that would cover another is left out, those at a limit first kept.
    const double k = m_style.scale;
    const QTransform world = p.worldTransform();
    std::vector<ProtractorLabel>& labels = m_protractorLabels; // capacities reused frame to frame
    labels.clear();
    for (int c = 0; c < sim()->chainCount(); ++c) {
        readLinkAngles(*sim(), c, m_joints, m_angles);
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
            sector << q(at);
            for (int i = 0; i <= n; ++i)
                sector << q(at + radius * seedDirection(a.reference + a.limit->min + span * i / n));
            const QColor colour = a.atLimit ? kAtLimitColour : kProtractorColour;
            QColor fill = colour;
            fill.setAlpha(40);
            QPen edge(colour, 1.2 * k);
            edge.setCosmetic(true);
            p.setPen(edge);
            p.setBrush(fill);
            p.drawPolygon(sector);
            const double degrees = std::round(a.angle * 180 / kPi) + 0.0; // + 0.0: a −0 reads 0
            labels.push_back({world.map(q(at + (radius + 12 * k * pixel) * seedDirection(a.reference + a.angle))),
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

void FrogCanvas::setRuler(const std::optional<std::pair<Point, Point>>& ruler)
{
    m_ruler = ruler;
    m_rulerDragging = m_rulerPlacing = false;
    update();
}

QString FrogCanvas::rulerText() const
{
    if (!m_ruler)
        return {};
    const Point d = m_ruler->second - m_ruler->first;
    return tr("%1 px (Δx %2, Δy %3)")
        .arg(displayFixed(std::sqrt(d.x * d.x + d.y * d.y), 1), displayFixed(d.x, 1), displayFixed(d.y, 1));
}

void FrogCanvas::drawRuler(QPainter& p, double pixel)
{
    const double k = m_style.scale;
    const Point a = m_ruler->first, b = m_ruler->second;
    const Point d = b - a;
    const double length = std::sqrt(d.x * d.x + d.y * d.y);
    const Point across = length > 0 ? Point(-d.y / length, d.x / length) : Point(0, 1);
    const double tick = 7 * k * pixel;
    p.save();
    for (const auto& [colour, width] : {std::pair{QColor(Qt::white), 4.0 * k}, std::pair{kRulerColour, 1.6 * k}}) {
        QPen pen(colour, width, Qt::SolidLine, Qt::FlatCap);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.drawLine(q(a), q(b));
        for (const Point& end : {a, b})
            p.drawLine(q(end - tick * across), q(end + tick * across));
    }
    // The length, beside the middle, on a pale box, kept inside the canvas.
    const QTransform world = p.worldTransform();
    const QString text = rulerText();
    p.resetTransform();
    p.setFont(m_numberFont);
    const QFontMetricsF fm(m_numberFont);
    QRectF box(0, 0, fm.horizontalAdvance(text) + 8 * k, fm.height() + 4 * k);
    box.moveCenter(world.map(q(0.5 * (a + b) + (2.2 * tick) * across)));
    box.moveLeft(std::clamp(box.left(), 0.0, std::max(0.0, width() - box.width())));
    box.moveTop(std::clamp(box.top(), 0.0, std::max(0.0, height() - box.height())));
    p.setPen(QPen(kRulerColour, 1));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRoundedRect(box, 3 * k, 3 * k);
    p.drawText(box, Qt::AlignCenter, text);
    p.restore();
}

void FrogCanvas::drawTrail(QPainter& p)
{
    m_trailSegmentsDrawn = 0;
    const std::deque<Point>& trail = m_run->trail();
    if (trail.size() < 2)
        return;
    // Square caps: Qt strokes a thick round cap as a curve, a hundred times slower.
    QPen pen(kTrailColour, 2 * m_style.scale, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin);
    pen.setCosmetic(true);
    // Only what the frame shows (the canvas clips to it), each segment cut to it and stroked
    // on its own: a blown-up seed's trail crosses the frame hundreds of times, and stroking it
    // as one path with round joins and caps (its outline overlapping itself everywhere) took
    // Qt 4.7 s a frame (tests/benchmarks/bench_gui.cpp, BM_GuiSeedExplodedTrail).
    const SceneSpec& scene = sim()->scene();
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

void FrogCanvas::setSceneSummary(const QString& summary)
{
    m_sceneSummary = summary;
    updateAccessibleDescription();
}

void FrogCanvas::updateAccessibleDescription()
{
    if (!sim() || sim()->bodyCount() == 0) {
        setAccessibleDescription(m_sceneSummary);
        return;
    }
    setAccessibleDescription(tr("%1; area error %2 %.").arg(m_sceneSummary, displayFixed(sim()->readouts().areaErrorPercent, 1)));
}

void FrogCanvas::refreshTexts()
{
    m_textClock.restart();
    updateAccessibleDescription();
    const auto mean = [](double& sum, int& count, double unit) {
        const double v = count > 0 ? sum / count / unit : 0;
        sum = 0;
        count = 0;
        return v;
    };
    m_run->averageTimings();
    if (m_draws > 0)
        m_drawShownMs = mean(m_drawNsSum, m_draws, 1e6);
    if (m_fits > 0)
        m_fitShownUs = mean(m_fitNsSum, m_fits, 1e3);
    emit fitCostChanged(m_fitShownUs);

    QStringList lines;
    const auto num = [](double v, int decimals) { return displayFixed(v, decimals); };
    const bool blownUpLine = sim() && m_run->blownUp(); // lines[0], wrapped to the canvas: it must be read whole
    if (sim()) {
        const SceneSpec& scene = sim()->scene();
        if (blownUpLine) {
            const double error = sim()->readouts().areaErrorPercent;
            lines << tr("The body has blown up (area error %1 %): press Reset (R), or switch to the Stable solver")
                         .arg(!std::isfinite(error) ? QStringLiteral("∞")
                                                    : (error > 0 ? QStringLiteral("+") : QString()) + displayFixed(error, 0));
        }
        if (const Simulation* ghost = m_run->ghost()) {
            const Simulation& g = *ghost;
            const bool seed = g.solver() == SolverKind::Seed;
            if (g.bodyCount() > 0)
                lines << (seed ? tr("Dashed ghost: the seed solver fed the same mouse, area error %1 %")
                               : tr("Dashed ghost: the stable solver fed the same mouse, area error %1 %"))
                             .arg(num(g.readouts().areaErrorPercent, 1));
            else
                lines << (seed ? tr("Dashed ghost: the seed solver fed the same mouse")
                               : tr("Dashed ghost: the stable solver fed the same mouse"));
        }
        if (m_overlays.pairs) {
            sim()->broadPhasePairs(m_pairs);
            lines << (sim()->solver() == SolverKind::Seed
                          ? tr("Broad phase: none, the seed has no collisions (§5.2 is future work)")
                          : tr("Broad phase: %n candidate pairs, %1 contacts", "", int(m_pairs.size()))
                                .arg(sim()->readouts().contacts));
        }
        if (m_overlays.protractor) {
            int limited = 0, held = 0;
            for (int c = 0; c < sim()->chainCount(); ++c) {
                readLinkAngles(*sim(), c, m_joints, m_angles);
                for (const LinkAngleReading& a : m_angles) {
                    limited += a.limit ? 1 : 0;
                    held += a.atLimit ? 1 : 0;
                }
            }
            lines << (limited == 0 ? tr("Protractor: no joint of this scene has angle limits")
                                   : tr("Protractor: %n of %1 joints held at a limit (red)", "", held).arg(limited));
        }
        if (m_overlays.trail)
            lines << (trailPoint().joint ? tr("Trail of joint %1 of chain %2 (Shift+click a point to follow another)")
                                         : tr("Trail of vertex %1 of body %2 (Shift+click a point to follow another)"))
                         .arg(trailPoint().index)
                         .arg(trailPoint().owner + 1);
        if (m_run->playingBack())
            lines << tr("Replaying the recorded run, step %1 of %2: a press on a body takes over from there")
                         .arg(sim()->stepCount())
                         .arg(m_run->recordedSteps());
        if (const int slower = m_run->workFramesPerStep(); slower > 1)
            lines << tr("Running %n× slower than real time: a step of this scene is more work than a frame holds", "", slower);
        if (speed() < 1)
            lines << tr("Slow motion, %1× real time: one step every %n frames, the step itself unchanged", "", framesPerStep())
                         .arg(speedLabel(speed()));
        else if (speed() > 1)
            lines << tr("Fast, %1× real time: %n steps a frame", "", stepsPerFrame()).arg(speedLabel(effectiveSpeed()));
        if (scene.has(SceneComponent::OutlineBezier)) {
            if (m_bezier == BezierOutline::Fit)
                lines << tr("Least-squares Bézier fit, degree %1 through %2 points: %3 µs per frame")
                             .arg(m_fitter ? m_fitter->degree() : scene.bezierFitDegree)
                             .arg(m_fitter ? m_fitter->vertexCount() + 1 : scene.bezierSamples + 1)
                             .arg(num(m_fitShownUs, 1));
            else
                lines << tr("Precomputed Bézier points (§4.9): computed once, nothing per frame");
        }
        // With several bodies each figure says whose it is: the area line is the first body's,
        // the solver's area error the mean over all of them.
        const int bodies = sim()->bodyCount();
        if (m_overlays.area && bodies > 0) {
            const double area = sim()->bodyArea(0), target = sim()->bodyTargetArea(0);
            if (bodies > 1 && target > 0)
                lines << tr("Body 1 of %1: area %2 px² · target %3 px² (%4 %)")
                             .arg(bodies)
                             .arg(num(area, 0), num(target, 0), num(100 * (area - target) / target, 1));
            else if (bodies > 1)
                lines << tr("Body 1 of %1: area %2 px² · target %3 px²").arg(bodies).arg(num(area, 0), num(target, 0));
            else if (target > 0)
                lines << tr("Area %1 px² · target %2 px² (%3 %)")
                             .arg(num(area, 0), num(target, 0), num(100 * (area - target) / target, 1));
            else
                lines << tr("Area %1 px² · target %2 px²").arg(num(area, 0), num(target, 0));
        }
        if (m_overlays.readouts) {
            const Readouts r = sim()->readouts();
            if (bodies > 1)
                lines << tr("Area error, mean of the %1 bodies, %2 % · largest stretch %3 %")
                             .arg(bodies)
                             .arg(num(r.areaErrorPercent, 2), num(100 * r.maxStretch, 1));
            else
                lines << tr("Area error %1 % · largest stretch %2 %").arg(num(r.areaErrorPercent, 2), num(100 * r.maxStretch, 1));
            lines << tr("Largest correction %1 · kinetic energy %2 · potential energy %3")
                         .arg(num(r.constraintForce, 3), num(r.kineticEnergy, 1), num(r.potentialEnergy, 0));
        }
        if (m_overlays.velocities && sim()->bodyCount() == 0)
            lines << tr("Velocities: this scene has no soft body");
        if (m_overlays.frameTime) {
            const double frameMs = m_run->frameMs(), stepMs = m_run->stepMs();
            if (running())
                lines << tr("Frame %1 ms (%2 frames per second) · step %3 ms · drawing %4 ms")
                             .arg(num(frameMs, 1), num(frameMs > 0 ? 1000 / frameMs : 0.0, 0), num(stepMs, 3),
                                  num(m_drawShownMs, 2));
            else
                lines << tr("Paused · step %1 ms · drawing %2 ms").arg(num(stepMs, 3), num(m_drawShownMs, 2));
            lines << tr("Step %1").arg(sim()->stepCount());
        }
    }
    const QFont& font = m_font;
    m_lines.resize(static_cast<std::size_t>(lines.size()));
    const double room = std::max(120.0, textPanelRoom());
    for (int i = 0; i < lines.size(); ++i) {
        QStaticText& t = m_lines[static_cast<std::size_t>(i)];
        t.setTextFormat(Qt::PlainText);
        t.setText(lines[i]);
        t.setTextWidth(i == 0 && blownUpLine ? room : -1);
        t.prepare(QTransform(), font);
        // A line wider than the canvas leaves (large text in presentation mode, a narrow
        // window) wraps at its spaces instead of running off the canvas.
        if (t.size().width() > room) {
            t.setTextWidth(room);
            t.prepare(QTransform(), font);
        }
    }
}

double FrogCanvas::textPanelRoom() const
{
    // What the text panel's margins and padding leave of the scene's width.
    return sceneRectIn(QRectF(rect())).width() - 2 * (kPanelMargin + kPanelPad) * m_style.scale;
}

double FrogCanvas::textPanelWidth() const
{
    double width = 0;
    for (const QStaticText& t : m_lines)
        width = std::max(width, t.size().width());
    return width;
}

// ---------------------------------------------------------------- coordinates

QRectF FrogCanvas::sceneRectIn(const QRectF& target) const
{
    const double W = sim() ? sim()->scene().params.width : 1280, H = sim() ? sim()->scene().params.height : 720;
    const double s = std::min(target.width() / W, target.height() / H);
    if (!(s > 0) || !std::isfinite(s))
        return {};
    return QRectF(target.center().x() - W * s / 2, target.center().y() - H * s / 2, W * s, H * s);
}

QPointF FrogCanvas::toWidget(const Point& p) const
{
    const QRectF r = sceneRectIn(QRectF(rect()));
    const double W = sim() ? sim()->scene().params.width : 1280;
    const double s = r.width() / W;
    return QPointF(r.left() + p.x * s, r.top() + p.y * s);
}

Point FrogCanvas::toScene(const QPointF& w) const
{
    const QRectF r = sceneRectIn(QRectF(rect()));
    const double W = sim() ? sim()->scene().params.width : 1280;
    const double s = r.width() / W;
    if (!(s > 0))
        return Point(0, 0);
    return Point((w.x() - r.left()) / s, (w.y() - r.top()) / s);
}

// ---------------------------------------------------------------- drawing

void FrogCanvas::paintEvent(QPaintEvent*)
{
    const qint64 t0 = m_clock.nsecsElapsed();
    QPainter p(this);
    render(p, QRectF(rect()));
    if (hasFocus()) { // on screen only: the keyboard cursor and the focus frame
        drawKeyboardCursor(p);
        drawFocusFrame(p, QRectF(rect()), palette(), m_style.scale);
    }
    m_drawNsSum += double(m_clock.nsecsElapsed() - t0);
    ++m_draws;
}

void FrogCanvas::render(QPainter& p, const QRectF& target) { renderScene(p, target, true); }

void FrogCanvas::renderFrame(QPainter& p, const QRectF& target) { renderScene(p, target, false); }

void FrogCanvas::renderScene(QPainter& p, const QRectF& target, bool textPanel)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setRenderHint(QPainter::SmoothPixmapTransform, true);
    p.fillRect(target, kLetterbox);
    const QRectF r = sceneRectIn(target);
    if (!sim() || r.width() < 1 || r.height() < 1) {
        p.restore();
        return;
    }
    const double W = sim()->scene().params.width, H = sim()->scene().params.height;
    // Bars above and below continue the sky and the mud; the frame's edge stays visible.
    if (r.top() > target.top() + 0.5) {
        p.fillRect(QRectF(target.left(), target.top(), target.width(), r.top() - target.top()), kSkyTop);
        p.fillRect(QRectF(target.left(), r.bottom(), target.width(), target.bottom() - r.bottom()), kMudBottom);
    }
    p.save();
    p.setPen(m_framePen);
    p.setBrush(Qt::NoBrush);
    p.drawRect(r.adjusted(-0.5, -0.5, 0.5, 0.5));
    // The frame's top edge, a thin line across the sky: say what it is.
    p.setPen(kFrameCaptionColour);
    p.setFont(m_numberFont);
    const QRectF caption = frameCaptionRect(target);
    p.drawText(caption, Qt::AlignRight | Qt::AlignVCenter,
               QFontMetricsF(m_numberFont).elidedText(frameCaption(), Qt::ElideRight, caption.width()));
    p.restore();
    p.setClipRect(r, Qt::IntersectClip);

    // The background: cached as a pixmap on screen, painted as vectors in every export.
    if (p.device() == this) {
        const double dpr = devicePixelRatioF();
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

    const QTransform base = p.worldTransform();
    p.save();
    p.translate(r.topLeft());
    const double s = r.width() / W;
    p.scale(s, s);
    const double pixel = 1 / s; // one widget pixel in scene pixels
    drawScene(p, pixel);
    if (m_run->ghost())
        drawGhost(p);
    if (m_overlays.trail)
        drawTrail(p);
    if (m_overlays.pairs)
        drawPairs(p);
    drawOverlays(p, pixel);
    if (m_overlays.protractor)
        drawProtractor(p, pixel);
    if (m_ruler)
        drawRuler(p, pixel);
    p.restore();
    p.setWorldTransform(base);
    // The text panel may run below a small scene (presentation mode on a narrow canvas): it
    // is clipped to the canvas, not to the scene.
    p.setClipRect(target);
    if (textPanel)
        drawTextPanel(p, r);
    p.restore();
}

QString FrogCanvas::frameCaption() const { return tr("Top of the frame: the scene's upper wall (y = 0)"); }

QRectF FrogCanvas::frameCaptionRect(const QRectF& target) const
{
    // Just above the line when the sky bar over the frame has room for it, else just below.
    const QRectF r = sceneRectIn(target);
    const double h = QFontMetricsF(m_numberFont).height() + 2, margin = 6 * m_style.scale;
    const double top = r.top() - target.top() >= h + 2 ? r.top() - h - 1 : r.top() + 1;
    return QRectF(r.left() + margin, top, r.width() - 2 * margin, h);
}

void FrogCanvas::drawGhost(QPainter& p)
{
    // The other solver's bodies and chains, pale and dashed over this one's: where they part
    // is what the two solvers do differently with the same input.
    const Simulation& g = *m_run->ghost();
    const double k = m_style.scale;
    QPen pen(kGhostColour, 2.5 * k, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin);
    pen.setCosmetic(true);
    p.save();
    p.setPen(pen);
    p.setBrush(QColor(255, 255, 255, 70));
    for (int i = 0; i < g.bodyCount(); ++i) {
        g.bodyVertices(i, m_work);
        fillPath(m_work, true);
        p.drawPath(m_path);
    }
    p.setBrush(Qt::NoBrush);
    for (int c = 0; c < g.chainCount(); ++c) {
        g.chainJoints(c, m_work);
        fillPath(m_work, false);
        p.drawPath(m_path);
    }
    p.restore();
}

void FrogCanvas::fillPath(const std::vector<Point>& points, bool close)
{
    m_path.clear();
    m_path.setFillRule(Qt::WindingFill);
    m_path.reserve(static_cast<int>(points.size()) + 1);
    bool started = false;
    for (const Point& pt : points) {
        if (!isFinite(pt))
            continue;
        if (started) {
            m_path.lineTo(pt.x, pt.y);
        } else {
            m_path.moveTo(pt.x, pt.y);
            started = true;
        }
    }
    if (close && started)
        m_path.closeSubpath();
}

void FrogCanvas::drawScene(QPainter& p, double pixel)
{
    const SceneSpec& scene = sim()->scene();
    if (scene.has(SceneComponent::Obstacles))
        drawObstacles(p);
    if (scene.model == SceneModel::Pendulum) {
        drawPendulum(p, pixel);
        return;
    }
    // Annex II, Granota.dibuixar: back legs, body, front legs, head.
    const bool frog = scene.model == SceneModel::Frog && sim()->chainCount() >= 4;
    if (frog) {
        drawLeg(p, 2, pixel);
        drawLeg(p, 3, pixel);
    }
    for (int i = 0; i < sim()->bodyCount(); ++i)
        drawBody(p, i, pixel);
    if (frog) {
        drawLeg(p, 0, pixel);
        drawLeg(p, 1, pixel);
    }
    if (scene.model == SceneModel::Frog && scene.has(SceneComponent::Head) && sim()->bodyCount() > 0) {
        sim()->bodyVertices(0, m_vertices);
        drawHead(p, 0);
    }
    drawMarkedBody(p, pixel);
}

void FrogCanvas::setMarkedBody(int body)
{
    m_run->setSeriesBodiesAsked(body >= 0); // a scene of many bodies keeps them only while asked
    if (body == m_markedBody)
        return;
    m_markedBody = body;
    update();
}

void FrogCanvas::drawMarkedBody(QPainter& p, double pixel)
{
    if (m_markedBody < 0 || m_markedBody >= sim()->bodyCount())
        return;
    sim()->bodyVertices(m_markedBody, m_work);
    if (m_work.size() < 3 || !std::all_of(m_work.begin(), m_work.end(), [](Point v) { return isFinite(v); }))
        return;
    const Aabb box = boundingBox(m_work.data(), int(m_work.size()));
    // Sizes in screen px (`pixel`: scene px per screen px), so the mark reads at any zoom.
    const double grow = 6 * m_style.scale * pixel;
    const QRectF around(QPointF(box.minX - grow, box.minY - grow), QPointF(box.maxX + grow, box.maxY + grow));
    p.save();
    QPen pen(kMarkedBodyColour, 2.5 * m_style.scale, Qt::DashLine);
    pen.setCosmetic(true);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    p.drawRoundedRect(around, grow, grow);
    // Its number, as the plots' list names it, above the box (below it at the frame's top).
    QFont font = p.font();
    font.setBold(true);
    font.setPixelSize(std::max(1, int(std::lround(15 * m_style.scale * pixel))));
    p.setFont(font);
    const QString label = QString::number(m_markedBody + 1);
    const QFontMetricsF metrics(font);
    const QSizeF size(metrics.horizontalAdvance(label) + 8 * m_style.scale * pixel, metrics.height() + 2 * m_style.scale * pixel);
    const double top = around.top() - size.height() >= 0 ? around.top() - size.height() : around.bottom();
    const QRectF tag(QPointF(around.center().x() - size.width() / 2, top), size);
    p.setPen(Qt::NoPen);
    p.setBrush(kMarkedBodyColour);
    p.drawRoundedRect(tag, 3 * m_style.scale * pixel, 3 * m_style.scale * pixel);
    p.setPen(Qt::white);
    p.drawText(tag, Qt::AlignCenter, label);
    p.restore();
}

void FrogCanvas::drawHead(QPainter& p, int body)
{
    const std::size_t n = m_vertices.size();
    if (n < 3 || !isFinite(m_vertices[0]) || !isFinite(m_vertices[1]) || !isFinite(m_vertices[n - 1]))
        return;
    const HeadPose pose = headPose(m_vertices);
    double target = sim()->bodyTargetArea(body);
    if (!(target > 0))
        target = sim()->bodyArea(body);
    const double scale = std::clamp(std::sqrt(std::max(target, 0.0) / kSeedTargetArea), 0.12, 3.0);
    const QPointF at = q(pose.centre);
    const QPointF look = m_mouseKnown ? q(m_mouse) : at + QPointF(0, 200);
    m_art.paintHead(p, at, pose.angle, scale, look);
}

void FrogCanvas::paintHeadOf(QPainter& p, int index)
{
    if (!sim() || index < 0 || index >= sim()->bodyCount())
        return;
    sim()->bodyVertices(index, m_vertices);
    drawHead(p, index);
}

HeadPose FrogCanvas::headPose(const std::vector<Point>& vertices) const
{
    // The seed draws the head as Annex II does: upright, its 138 × 93 box at vertex 0 − (69, 46)
    // (head_pose.h). The stable solver keeps Granota's head, turned with the body.
    return sim()->solver() == SolverKind::Seed ? annexIIHeadPose(vertices) : turningHeadPose(vertices);
}

HeadPose FrogCanvas::headPose(int body)
{
    sim()->bodyVertices(body, m_work);
    return headPose(m_work);
}

const std::vector<Point>& FrogCanvas::bodyOutline(int body)
{
    const SceneSpec& scene = sim()->scene();
    sim()->bodyVertices(body, m_vertices);
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

void FrogCanvas::drawBody(QPainter& p, int body, double pixel)
{
    const SceneSpec& scene = sim()->scene();
    const std::vector<Point>& outline = bodyOutline(body);
    if (m_vertices.size() < 2)
        return;
    fillPath(outline, true);
    if (scene.has(SceneComponent::Fill)) {
        p.setBrush(m_art.skin(body));
        p.setPen(m_art.bodyPen());
    } else {
        p.setBrush(Qt::NoBrush);
        // §4.1–4.7's bare polygon: never thinner than kInkMinimumPx on screen (its 3 scene px
        // were 1 px on a small canvas, too faint for a projector), thicker in presentation mode.
        QPen ink = m_art.inkPen();
        ink.setWidthF(std::max(ink.widthF(), kInkMinimumPx * m_style.scale * pixel));
        p.setPen(ink);
    }
    p.drawPath(m_path);
    if (scene.has(SceneComponent::Head) && scene.model != SceneModel::Frog)
        drawHead(p, body);
}

void FrogCanvas::drawLeg(QPainter& p, int chain, double)
{
    sim()->chainJoints(chain, m_joints);
    if (m_joints.size() < 3)
        return;
    const Point &m = m_joints[0], &e = m_joints[1], &w = m_joints[2];
    if (!isFinite(m) || !isFinite(e) || !isFinite(w))
        return;
    const Point bone = w - e;
    const double footAngle = norm(bone) > 1e-9 ? std::atan2(bone.y, bone.x) : kPi / 2;
    m_art.paintFoot(p, q(w), footAngle, chain < 2 ? 0.8 : 1.0);
    sampleLegOutline(m, e, w, kLegFactor, 6, m_outline);
    fillPath(m_outline, true);
    p.setBrush(m_art.skin(0));
    p.setPen(m_art.legPen());
    p.drawPath(m_path);
}

void FrogCanvas::drawPendulum(QPainter& p, double)
{
    for (int c = 0; c < sim()->chainCount(); ++c) {
        sim()->chainJoints(c, m_joints);
        if (m_joints.empty())
            continue;
        fillPath(m_joints, false);
        p.setBrush(Qt::NoBrush);
        p.setPen(m_art.rodPen());
        p.drawPath(m_path);
        p.setPen(m_art.jointPen());
        for (std::size_t k = 1; k < m_joints.size(); ++k) {
            if (!isFinite(m_joints[k]))
                continue;
            p.setBrush(m_art.jointBrush());
            p.drawEllipse(q(m_joints[k]), 10 * m_style.scale, 10 * m_style.scale);
        }
        if (isFinite(m_joints[0])) { // the clau the pendulum hangs from (§4.14)
            p.setBrush(m_art.pinBrush());
            p.drawEllipse(q(m_joints[0]), 8 * m_style.scale, 8 * m_style.scale);
            p.setBrush(m_art.whiteBrush());
            p.setPen(Qt::NoPen);
            p.drawEllipse(q(m_joints[0]), 3 * m_style.scale, 3 * m_style.scale);
        }
    }
}

void FrogCanvas::drawObstacles(QPainter& p)
{
    for (const ObstacleSpec& o : sim()->obstacles()) {
        fillPath(o.points, o.closed);
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

void FrogCanvas::drawOverlays(QPainter& p, double pixel)
{
    const Overlays& o = m_overlays;
    if (!o.vertices && !o.springs && !o.velocities)
        return;
    const double k = m_style.scale;
    const double dot = 3.5 * k * pixel;

    const auto drawPoints = [&](const std::vector<Point>& pts, bool closed) {
        if (o.springs) {
            fillPath(pts, closed);
            p.setBrush(Qt::NoBrush);
            p.setPen(m_edgePen);
            p.drawPath(m_path);
        }
    };
    for (int i = 0; i < sim()->bodyCount(); ++i) {
        sim()->bodyVertices(i, m_vertices);
        drawPoints(m_vertices, true);
        const std::vector<std::size_t>& offset = m_run->previousOffset();
        if (o.velocities && m_run->previousValid() && std::size_t(i) + 1 < offset.size() &&
            offset[std::size_t(i) + 1] - offset[std::size_t(i)] == m_vertices.size()) {
            p.setPen(m_velocityPen);
            const Point* prev = m_run->previous().data() + offset[std::size_t(i)];
            for (std::size_t v = 0; v < m_vertices.size(); ++v) {
                const Point tip = m_vertices[v] + kVelocityScale * (m_vertices[v] - prev[v]);
                if (isFinite(tip) && isFinite(m_vertices[v]))
                    p.drawLine(q(m_vertices[v]), q(tip));
            }
        }
        if (o.vertices) {
            p.setPen(m_ringPen);
            p.setBrush(m_art.whiteBrush());
            for (const Point& v : m_vertices)
                if (isFinite(v))
                    p.drawEllipse(q(v), dot, dot);
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
                        p.drawText(world.map(q(m_vertices[v])) + QPointF(5 * k, -5 * k), m_numbers[v]);
                p.restore();
            }
        }
    }
    for (int c = 0; c < sim()->chainCount(); ++c) {
        sim()->chainJoints(c, m_joints);
        drawPoints(m_joints, false);
        if (o.vertices) {
            p.setPen(m_ringPen);
            p.setBrush(m_jointDotBrush);
            for (const Point& v : m_joints)
                if (isFinite(v))
                    p.drawEllipse(q(v), dot, dot);
        }
    }
}

void FrogCanvas::drawTextPanel(QPainter& p, const QRectF& sceneRect)
{
    const bool bar = m_overlays.area && sim()->bodyCount() > 0;
    if (m_lines.empty() && !bar)
        return;
    const double k = m_style.scale, margin = kPanelMargin * k, pad = kPanelPad * k;
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
        const double area = sim()->bodyArea(0), target = sim()->bodyTargetArea(0);
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

// ---------------------------------------------------------------- mouse and keys

void FrogCanvas::mousePressEvent(QMouseEvent* event)
{
    if (!sim())
        return;
    setFocus(Qt::MouseFocusReason);
    m_mouse = toScene(event->position());
    m_mouseKnown = true;
    const bool measure = event->button() == Qt::RightButton ||
                         (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier));
    if (measure) { // the ruler: measuring grabs nothing and records nothing
        m_ruler = std::pair{m_mouse, m_mouse};
        m_rulerDragging = true;
        m_rulerPlacing = false;
        update();
        return;
    }
    if (event->button() != Qt::LeftButton)
        return;
    if (m_overlays.trail && (event->modifiers() & Qt::ShiftModifier)) { // choose the trail's point, grab nothing
        if (!chooseTrailPoint(m_mouse))
            emit statusMessage(tr("Shift+click on a vertex or a joint to follow it with the trail."));
        return;
    }
    // Annex II, mousePressed: grab when the cursor is inside the body. Going back in a run
    // (docs/rewind.md), a press that grabs nothing leaves the recorded future alone.
    if (m_run->playingBack() && !m_run->wouldGrab(m_mouse)) {
        emit statusMessage(
            tr("Playing the recorded run back: press inside a body to take over from step %1.").arg(sim()->stepCount()));
        return;
    }
    m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    m_pressed = true;
    const bool held = m_run->send(InputKind::Press, m_mouse);
    if (held && sim()->grabbing())
        setCursor(Qt::ClosedHandCursor);
    else if (!held && sim()->scene().has(SceneComponent::Grab))
        emit statusMessage(tr("Press inside the body to grab it."));
    update();
}

void FrogCanvas::mouseMoveEvent(QMouseEvent* event)
{
    if (!sim())
        return;
    m_mouse = toScene(event->position());
    m_mouseKnown = true;
    if ((m_rulerDragging || m_rulerPlacing) && m_ruler) {
        m_ruler->second = m_mouse;
        update();
    }
    if (m_pressed || !m_run->playingBack()) // hovering over a run played back changes nothing
        m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    if (!m_pressed && sim()->scene().has(SceneComponent::Grab)) {
        if (insideABody(m_mouse))
            setCursor(Qt::OpenHandCursor);
        else
            unsetCursor();
    }
    if (!running())
        update(); // the eyes follow the mouse even when paused
}

void FrogCanvas::reportMouseRadius()
{
    const std::optional<double> r = sim() ? sim()->mouseRadius() : std::nullopt;
    if (r && *r != m_reportedRadius) {
        m_reportedRadius = *r;
        emit mouseRadiusChanged(*r);
    }
}

void FrogCanvas::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_rulerDragging && (event->button() == Qt::RightButton || event->button() == Qt::LeftButton)) {
        m_rulerDragging = false;
        const QPointF from = toWidget(m_ruler->first), to = toWidget(m_ruler->second);
        if ((from - to).manhattanLength() < 3) // a click, not a drag: clears the ruler
            m_ruler.reset();
        else
            emit statusMessage(tr("Ruler: %1. Esc or a right click clears it.").arg(rulerText()));
        update();
        return;
    }
    if (!sim() || event->button() != Qt::LeftButton || !m_pressed)
        return;
    m_keyboardHeld = false;
    m_run->send(InputKind::Release); // Annex II, mouseReleased
    m_pressed = false;
    unsetCursor();
    update();
}

void FrogCanvas::drawKeyboardCursor(QPainter& p) const
{
    if (!sim())
        return;
    const QPointF c = toWidget(m_mouse);
    const double k = m_style.scale, r = 9 * k;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    for (const auto& [colour, width] :
         {std::pair{QColor(Qt::white), 4.0 * k}, std::pair{palette().color(QPalette::Highlight), 2.0 * k}}) {
        p.setPen(QPen(colour, width));
        p.drawEllipse(c, r, r);
        p.drawLine(c - QPointF(2 * r, 0), c - QPointF(r, 0));
        p.drawLine(c + QPointF(r, 0), c + QPointF(2 * r, 0));
        p.drawLine(c - QPointF(0, 2 * r), c - QPointF(0, r));
        p.drawLine(c + QPointF(0, r), c + QPointF(0, 2 * r));
    }
    p.restore();
}

bool FrogCanvas::insideABody(Point at)
{
    for (int i = 0; i < sim()->bodyCount(); ++i) {
        sim()->bodyVertices(i, m_vertices);
        if (pointInPolygon(at, m_vertices))
            return true;
    }
    return false;
}

Point FrogCanvas::bodyCentre(int body)
{
    sim()->bodyVertices(body, m_vertices);
    Point sum{0, 0};
    for (const Point& v : m_vertices)
        sum = {sum.x + v.x / double(m_vertices.size()), sum.y + v.y / double(m_vertices.size())};
    return sum;
}

Point FrogCanvas::keyboardCursorStart()
{
    // On the body nearest the middle of the view, where the keys can grab it at once (the
    // view's middle if the scene has none), never in a corner half out of sight.
    const Point middle = toScene(QPointF(rect().center()));
    if (const int body = nearestBody(middle); body >= 0)
        return bodyCentre(body);
    return middle;
}

void FrogCanvas::placeKeyboardCursor()
{
    if (m_mouseKnown || !sim())
        return;
    m_mouse = keyboardCursorStart();
    m_mouseKnown = true;
}

int FrogCanvas::nearestBody(Point at)
{
    int best = -1;
    double bestDistance = 0;
    for (int i = 0; i < sim()->bodyCount(); ++i) {
        sim()->bodyVertices(i, m_vertices);
        for (const Point& v : m_vertices) {
            const double d = std::hypot(v.x - at.x, v.y - at.y);
            if (best < 0 || d < bestDistance) {
                best = i;
                bestDistance = d;
            }
        }
    }
    return best;
}

bool FrogCanvas::keyboardGrab()
{
    if (!sim() || m_pressed)
        return false;
    placeKeyboardCursor();
    // Outside every body, the cursor first jumps to the centre of the nearest one.
    if (const int body = insideABody(m_mouse) ? -1 : nearestBody(m_mouse); body >= 0)
        m_mouse = bodyCentre(body);
    if (m_run->playingBack() && !m_run->wouldGrab(m_mouse)) {
        emit statusMessage(tr("Playing the recorded run back: move the cursor inside a body to take over from step %1.")
                               .arg(sim()->stepCount()));
        update();
        return false;
    }
    m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    m_pressed = m_run->send(InputKind::Press, m_mouse);
    m_keyboardHeld = m_pressed;
    if (!m_pressed && sim()->scene().has(SceneComponent::Grab))
        emit statusMessage(tr("Nothing to grab here: move the cursor inside the body with the arrows."));
    update();
    return m_pressed;
}

void FrogCanvas::keyboardRelease()
{
    if (!sim() || !m_keyboardHeld)
        return;
    m_run->send(InputKind::Release);
    m_pressed = false;
    m_keyboardHeld = false;
    update();
}

void FrogCanvas::moveKeyboardCursor(double dx, double dy)
{
    if (!sim())
        return;
    placeKeyboardCursor();
    const double W = sim()->scene().params.width, H = sim()->scene().params.height;
    m_mouse = {std::clamp(m_mouse.x + dx, 0.0, W - 1), std::clamp(m_mouse.y + dy, 0.0, H - 1)};
    if (m_rulerPlacing && m_ruler)
        m_ruler->second = m_mouse;
    if (m_pressed || !m_run->playingBack())
        m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    update();
}

void FrogCanvas::keyPressEvent(QKeyEvent* event)
{
    // The keyboard's grab (docs/classroom.md): the arrows move the cursor (Shift: five times
    // further), G or Enter grabs at it and lets go, Esc lets go.
    const double step = kKeyboardStep * (event->modifiers() & Qt::ShiftModifier ? 5 : 1);
    switch (event->key()) {
    case Qt::Key_Left: moveKeyboardCursor(-step, 0); return;
    case Qt::Key_Right: moveKeyboardCursor(step, 0); return;
    case Qt::Key_Up: moveKeyboardCursor(0, -step); return;
    case Qt::Key_Down: moveKeyboardCursor(0, step); return;
    case Qt::Key_G:
    case Qt::Key_Return:
    case Qt::Key_Enter:
        if (event->isAutoRepeat())
            return;
        if (m_keyboardHeld)
            keyboardRelease();
        else
            keyboardGrab();
        return;
    case Qt::Key_Escape:
        if (m_keyboardHeld) {
            keyboardRelease();
            return;
        }
        if (m_ruler) {
            m_ruler.reset();
            m_rulerPlacing = m_rulerDragging = false;
            update();
            return;
        }
        break;
    case Qt::Key_L: // the ruler from the keyboard: one end at the cursor, the arrows, L again
        if (event->isAutoRepeat() || !sim())
            return;
        placeKeyboardCursor();
        if (m_rulerPlacing) {
            m_rulerPlacing = false;
            emit statusMessage(tr("Ruler: %1. Esc or a right click clears it.").arg(rulerText()));
        } else {
            m_ruler = std::pair{m_mouse, m_mouse};
            m_rulerPlacing = true;
            emit statusMessage(tr("Ruler: move the cursor with the arrows to the other end, then L."));
        }
        update();
        return;
    default: break;
    }
    if (event->key() != Qt::Key_Space) {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || !sim() || m_spawnHeld)
        return;
    // Annex II, keyPressed(' '): a new frog at the mouse, held until the key is released.
    if (!m_mouseKnown) {
        m_mouse = toScene(mapFromGlobal(QCursor::pos()));
        m_mouseKnown = true;
    }
    m_run->send(InputKind::Spawn, m_mouse); // a new body: more work a step
    m_spawnHeld = true;
    update();
}

void FrogCanvas::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Space) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || !m_spawnHeld)
        return;
    m_spawnHeld = false;
    if (sim())
        m_run->send(InputKind::ReleaseSpawn); // Annex II, keyReleased(' ')
    update();
}

void FrogCanvas::enterEvent(QEnterEvent* event)
{
    // The space bar belongs to the canvas as soon as the mouse is over it (unless a number
    // is being typed in a field).
    if (!qobject_cast<QAbstractSpinBox*>(QApplication::focusWidget()))
        setFocus(Qt::MouseFocusReason);
    QWidget::enterEvent(event);
}

void FrogCanvas::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_run->setShown(isVisible());
}

void FrogCanvas::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (sim())
        refreshTexts();
}

void FrogCanvas::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event); // a hidden tab costs nothing
    m_run->setShown(isVisible());
}

void FrogCanvas::focusInEvent(QFocusEvent* event)
{
    // The cursor is drawn where the keys will start, but the scene is not told of a mouse
    // until a key moves or uses it (the §4.1 polygon's radius follows the mouse).
    if (!m_mouseKnown && sim())
        m_mouse = keyboardCursorStart();
    update(); // the focus frame and the keyboard cursor
    QWidget::focusInEvent(event);
}

void FrogCanvas::focusOutEvent(QFocusEvent* event)
{
    keyboardRelease();
    update();
    // The key release would go elsewhere: let go of a frog held by the space bar now.
    if (m_spawnHeld && sim())
        m_run->send(InputKind::ReleaseSpawn);
    m_spawnHeld = false;
    QWidget::focusOutEvent(event);
}

void FrogCanvas::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::FontChange)
        buildPens();
    if (event->type() == QEvent::LanguageChange || event->type() == QEvent::FontChange)
        refreshTexts();
    QWidget::changeEvent(event);
}

} // namespace granota::ui
