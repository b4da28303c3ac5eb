#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/common/number_text.h"

#include "core/base/aabb.h"
#include "core/base/math_constants.h"
#include "core/base/number_format.h"
#include "core/curves/bezier/bernstein_properties.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bezier/hodograph.h"
#include "core/exact/rational.h"
#include "core/exact/rational_approximation.h"
#include "core/io/worked_examples.h"
#include "ui/common/bezier_curve_model.h"
#include "ui/common/bezier_exact_html.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/curve_canvas.h"
#include "ui/decasteljau/decasteljau_construction_drawing.h"
#include "ui/decasteljau/decasteljau_curve_drag.h"
#include "ui/decasteljau/decasteljau_flow_layout.h"
#include "ui/decasteljau/decasteljau_parameter_control.h"
#include "ui/decasteljau/decasteljau_scene_painter.h"
#include "ui/decasteljau/decasteljau_tikz.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "ui/common/tab_order.h"
#include "ui/common/value_command.h"
#include "ui/common/widest_text_width.h"
#include "ui/files/tikz_writer.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <limits>
#include <cmath>
#include <optional>

namespace granota::ui {

namespace {

constexpr int kAnimationMs = 30;                         ///< timer period of the t animation
constexpr int kPanelMs = 100;                            ///< exact panel refresh period while dragging or playing
constexpr double kAnimationStep = 0.004;                 ///< t per tick: one sweep of [0, 1] in about 7.5 s
constexpr int kDeCasteljauSamplesMergeId = 0x44430001;   ///< "DC": the samples' spin box held down is one step
constexpr int kDeCasteljauCombScaleMergeId = 0x44430002; ///< and the comb's scale's

/// Ex 2.2-like default: a cubic with four points.
std::vector<Point> defaultPoints() { return {{0, 0}, {1, 2}, {3, 2}, {4, 0}}; }

} // namespace

DeCasteljauTab::DeCasteljauTab(QWidget* parent) : CurveTab(QStringLiteral("decasteljau"), QT_TR_NOOP("De Casteljau"), parent)
{
    buildLayers(); // under the handles: the editor adds its own layer on top
    m_editor = new PointEditor(m_canvas, m_undo, this);
    m_editor->setCountLimits(1, kMaxPoints);
    m_editor->setLabelPrefix(QStringLiteral("P"));
    m_model = new BezierCurveModel(m_editor, m_undo, this);
    m_table = new PointTable(m_editor, this);
    m_curveDrag = new DeCasteljauCurveDrag(m_canvas, m_editor, m_undo, this); // after the editor: sees the mouse first
    m_exact = new ExactPanel(this);
    // Break lines only between words: wide tables scroll sideways instead of splitting "(1/2, 3)".
    m_exact->setWordWrapMode(QTextOption::WordWrap);

    // The controls, in two compact rows above the canvas.
    m_parameter = new DeCasteljauParameterControl(this);
    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("decasteljauPlay"));
    m_play->setCheckable(true);
    m_play->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_timer = new QTimer(this);
    m_timer->setInterval(kAnimationMs);
    // While a point is dragged or t is animated the canvas follows every frame; the exact
    // panel (hundreds of typeset entries at high degree) at most every kPanelMs, and at once
    // when the point is dropped.
    m_panelTimer = new QTimer(this);
    m_panelTimer->setSingleShot(true);
    m_panelTimer->setInterval(kPanelMs);
    connect(m_panelTimer, &QTimer::timeout, this, &DeCasteljauTab::refreshPanel);
    m_samplesLabel = new QLabel(this);
    m_samplesBox = new QSpinBox(this);
    m_samplesBox->setRange(DeCasteljauView::kMinSamples, DeCasteljauView::kMaxSamples);
    m_samplesBox->setKeyboardTracking(false);
    m_samplesLabel->setBuddy(m_samplesBox);
    m_raise = new QPushButton(this);
    m_controlPoints = new QCheckBox(this);
    m_construction = new QCheckBox(this);
    m_steps = new QCheckBox(this);
    m_tangent = new QCheckBox(this);
    m_split = new QCheckBox(this);
    m_snap = new QCheckBox(this);
    m_normal = new QCheckBox(this);
    m_osculating = new QCheckBox(this);
    m_combBox = new QCheckBox(this);
    m_combScaleLabel = new QLabel(this);
    m_combScaleBox = new CurvatureCombScaleBox(this);
    m_combScaleLabel->setBuddy(m_combScaleBox);
    m_box = new QCheckBox(this);
    m_featuresBox = new QCheckBox(this);
    m_hodograph = new QCheckBox(this);
    m_speed = new QCheckBox(this);
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("decasteljauReadout"));
    m_readout->setWordWrap(true);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_warningLabel = new QLabel(this);
    m_warningLabel->setWordWrap(true);
    m_warningLabel->setStyleSheet(QStringLiteral("color: #8a3a00;"));
    m_warningLabel->hide();

    auto* row1 = new QHBoxLayout;
    row1->addWidget(m_parameter, 1);
    row1->addWidget(m_play);
    // The rest wraps onto more rows when the width runs out (Catalan, presentation mode).
    auto* samples = new QWidget(this);
    auto* samplesLayout = new QHBoxLayout(samples);
    samplesLayout->setContentsMargins(0, 0, 0, 0);
    samplesLayout->addWidget(m_samplesLabel);
    samplesLayout->addWidget(m_samplesBox);
    auto* row2 = new DeCasteljauFlowLayout;
    for (QCheckBox* box : {m_controlPoints, m_construction, m_steps, m_tangent, m_split, m_speed, m_snap})
        row2->addWidget(box);
    row2->addWidget(samples);
    row2->addWidget(m_raise);

    auto* left = new QWidget(this);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addLayout(row1);
    leftLayout->addLayout(row2);
    leftLayout->addWidget(m_canvas, 1);
    leftLayout->addWidget(m_warningLabel);

    m_sideSplitter = new QSplitter(Qt::Vertical, this);
    m_sideSplitter->addWidget(m_table);
    m_sideSplitter->addWidget(m_exact);
    m_sideSplitter->setStretchFactor(0, 1);
    m_sideSplitter->setStretchFactor(1, 3);
    m_sideSplitter->setSizes({200, 560});
    m_mainSplitter = new QSplitter(Qt::Horizontal, this);
    m_mainSplitter->addWidget(left);
    // Beside the canvas, above the table: the overlays of the curve's geometry and the readouts.
    auto* geometry = new QWidget(this);
    geometry->setObjectName(QStringLiteral("geometry"));
    auto* geometryLayout = new QVBoxLayout(geometry);
    geometryLayout->setContentsMargins(0, 0, 0, 0);
    auto* overlays = new DeCasteljauFlowLayout(nullptr, 10, 2);
    // The comb's scale beside its toggle.
    auto* comb = new QWidget(this);
    auto* combLayout = new QHBoxLayout(comb);
    combLayout->setContentsMargins(0, 0, 0, 0);
    combLayout->addWidget(m_combBox);
    combLayout->addWidget(m_combScaleLabel);
    combLayout->addWidget(m_combScaleBox);
    for (QWidget* box : std::initializer_list<QWidget*>{m_normal, m_osculating, comb, m_box, m_featuresBox, m_hodograph})
        overlays->addWidget(box);
    geometryLayout->addLayout(overlays);
    geometryLayout->addWidget(m_readout);
    auto* side = new QWidget(this);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(geometry);
    sideLayout->addWidget(m_sideSplitter, 1);
    m_mainSplitter->addWidget(side);
    setSidePanel(side);
    m_mainSplitter->setStretchFactor(0, 3);
    m_mainSplitter->setStretchFactor(1, 2);
    m_mainSplitter->setSizes({780, 480});
    m_mainSplitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_mainSplitter);
    // Tab as the tab reads: t and the rows above the canvas, the canvas, then the side panel
    // top to bottom (the canvas, the table and the exact panel were made first).
    setTabOrderOf({m_parameter, m_play,         m_controlPoints, m_construction, m_steps,     m_tangent, m_split,
                   m_speed,     m_snap,         m_samplesBox,    m_raise,        m_canvas,    m_normal,  m_osculating,
                   m_combBox,   m_combScaleBox, m_box,           m_featuresBox,  m_hodograph, m_table,   m_exact});

    connect(m_editor, &PointEditor::pointsChanged, this, &DeCasteljauTab::pointsChanged);
    connect(m_model, &BezierCurveModel::tChanged, this, [this](double t) {
        m_parameter->setValue(t);
        parameterChanged();
    });
    connect(m_model, &BezierCurveModel::documentChanged, this, &TabPage::documentChanged);
    connect(m_model, &BezierCurveModel::curveLoading, this, [this] { setPlaying(false); });
    connect(m_model, &BezierCurveModel::curveLoaded, this, &DeCasteljauTab::fitView);
    connect(m_editor, &PointEditor::message, this, &TabPage::statusMessage);
    connect(m_table, &PointTable::message, this, &TabPage::statusMessage);
    connect(m_curveDrag, &DeCasteljauCurveDrag::message, this, &TabPage::statusMessage);
    m_curveDrag->setParameterSource([this] { return m_model->t(); });
    connect(m_parameter, &DeCasteljauParameterControl::valueChanged, this, &DeCasteljauTab::userMovedT);
    connect(m_play, &QToolButton::toggled, this, &DeCasteljauTab::setPlaying);
    connect(m_timer, &QTimer::timeout, this, &DeCasteljauTab::advanceAnimation);
    connect(m_samplesBox, &QSpinBox::valueChanged, this, [this](int part) {
        DeCasteljauView after = m_view;
        after.samples = part;
        after = after.clamped();
        userChangedView(after, tr("Samples: %1").arg(after.samples), kDeCasteljauSamplesMergeId);
    });
    connect(m_combScaleBox, &QDoubleSpinBox::valueChanged, this, [this](double scale) {
        DeCasteljauView after = m_view;
        after.combScale = scale;
        userChangedView(after, tr("Comb scale"), kDeCasteljauCombScaleMergeId);
    });
    connect(m_raise, &QPushButton::clicked, this, &DeCasteljauTab::raiseDegree);
    for (const Toggle& toggle : toggles())
        connect(toggle.box, &QCheckBox::toggled, this, [this, toggle](bool on) {
            DeCasteljauView after = m_view;
            after.*toggle.flag = on;
            userChangedView(after, tr(toggle.undoText));
        });

    showView();
    m_editor->applyPoints(defaultPoints());
    m_parameter->setValue(m_model->t());
    m_canvas->setContentBounds(contentBounds());
    retranslate();
}

// ---------------------------------------------------------------- drawing

std::vector<DeCasteljauTab::Toggle> DeCasteljauTab::toggles() const
{
    // The undo texts are the check boxes' own.
    return {{m_controlPoints, &DeCasteljauView::controlPoints, QT_TR_NOOP("Control points")},
            {m_construction, &DeCasteljauView::construction, QT_TR_NOOP("Construction")},
            {m_steps, &DeCasteljauView::stepByStep, QT_TR_NOOP("Step by step")},
            {m_tangent, &DeCasteljauView::tangent, QT_TR_NOOP("Tangent")},
            {m_split, &DeCasteljauView::split, QT_TR_NOOP("Split at t")},
            {m_snap, &DeCasteljauView::snap, QT_TR_NOOP("Snap to grid")},
            {m_normal, &DeCasteljauView::normal, QT_TR_NOOP("Normal")},
            {m_osculating, &DeCasteljauView::osculatingCircle, QT_TR_NOOP("Osculating circle")},
            {m_combBox, &DeCasteljauView::comb, QT_TR_NOOP("Curvature comb")},
            {m_box, &DeCasteljauView::boundingBox, QT_TR_NOOP("Bounding box")},
            {m_featuresBox, &DeCasteljauView::inflections, QT_TR_NOOP("Inflections and cusps")},
            {m_hodograph, &DeCasteljauView::hodograph, QT_TR_NOOP("Hodograph")},
            {m_speed, &DeCasteljauView::constantSpeed, QT_TR_NOOP("Constant speed")}};
}

void DeCasteljauTab::buildLayers()
{
    // The scene's layers (decasteljau_scene_painter.h), each in a painter state of its own.
    for (const DeCasteljauLayer draw : deCasteljauLayers())
        m_canvas->addLayer(
            [this, draw](QPainter& p, const ViewTransform& view, const CanvasStyle& style) { draw(p, view, style, m_scene); });
    // Over everything, the handles and their labels too: the hodograph c′ in an inset of its
    // own, with its own construction at t, and the key to the colours (which level, which step
    // curve, which half) in the corner where it covers least.
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_view.hodograph)
            drawDeCasteljauHodographInset(p, view, style, m_scene, m_editor->labelPrefix());
    });
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        drawCanvasLegend(p, view, style, legend(), legendBox(view, style));
    });
}

// ---------------------------------------------------------------- updates

double DeCasteljauTab::splitSquareSide(const CanvasStyle& style) { return deCasteljauSplitSquareSide(style); }

CanvasLegend DeCasteljauTab::legend() const { return deCasteljauLegend(m_scene); }

QRectF DeCasteljauTab::legendRect(const ViewTransform& view, const CanvasStyle& style) const
{
    return legendBox(view, style).box;
}

CanvasLegendBox DeCasteljauTab::legendBox(const ViewTransform& view, const CanvasStyle& style) const
{
    return deCasteljauLegendBox(m_scene, m_editor->labelPrefix(), view, style);
}

CanvasLegendObstacles DeCasteljauTab::drawnObstacles(const ViewTransform& view, const CanvasStyle& style) const
{
    return deCasteljauObstacles(m_scene, m_editor->labelPrefix(), view, style);
}

QRectF DeCasteljauTab::hodographInset(const ViewTransform& view, const CanvasStyle& style) const
{
    return deCasteljauHodographInset(m_scene, m_editor->labelPrefix(), view, style);
}

void DeCasteljauTab::recomputeScene()
{
    m_scene = computeScene(m_editor->points(), m_editor->allExactPoints(), m_model->t(), m_view);
    m_combScaleBox->setEnabled(m_view.comb);
    m_combScaleLabel->setEnabled(m_view.comb);
    if (m_view.comb && m_view.combScale == 0 && m_scene.finite)
        m_combScaleBox->setAutomaticScale(m_scene.comb.scale);
}

double DeCasteljauTab::arcLengthAtT() const { return m_scene.arc ? m_scene.arc->lengthAt(m_model->t()) : 0.0; }
double DeCasteljauTab::totalLength() const { return m_scene.arc ? m_scene.arc->total() : 0.0; }

QString DeCasteljauTab::readout() const
{
    if (m_editor->points().empty() || !m_scene.arc)
        return QString();
    const QString lengths = tr("s(t) = %1 of L = %2").arg(panelNumber(arcLengthAtT()), panelNumber(totalLength()));
    const CurvatureAt& curvature = m_scene.curvature;
    QString kappa;
    if (!curvature.curvature)
        kappa = tr("κ(t) undefined: c′(t) = 0 (a cusp, or coincident control points)");
    else if (*curvature.curvature == 0.0)
        kappa = tr("κ(t) = 0: straight here, the radius is infinite");
    else
        kappa = tr("κ(t) = %1 (radius %2)").arg(panelNumber(*curvature.curvature), panelNumber(curvature.radius.value_or(0)));
    return lengths + QStringLiteral(" · ") + kappa;
}

void DeCasteljauTab::updateReadout()
{
    // The lengths on one line, the curvature on the next: as t plays, the numbers change
    // their width, and one long line would wrap at some t and not at others (the panel jumped).
    QString text = readout();
    const int joint = text.indexOf(QStringLiteral(" · "));
    if (joint >= 0)
        text.replace(joint, 3, QLatin1Char('\n'));
    m_readout->setText(text);
}

void DeCasteljauTab::pointsChanged()
{
    m_canvas->setDataExtent(contentBounds()); // points near ±1e308 get a notice, not a blank canvas
    if (m_editor->points().empty())
        return;
    recomputeScene();
    updateReadout();
    updateCanvasSummary();
    if (m_editor->dragging() || isPlaying() || m_curveDrag->molding()) {
        schedulePanel();
    } else {
        m_panelTimer->stop();
        refreshPanel();
    }
    m_canvas->update();
    emit documentChanged();
}

void DeCasteljauTab::refreshPanel()
{
    // The warning first: the panel ends with it.
    updateWarning();
    updateExactSymbolic();
    updateExactPanel();
}

void DeCasteljauTab::schedulePanel()
{
    if (!m_panelTimer->isActive())
        m_panelTimer->start();
}

void DeCasteljauTab::parameterChanged()
{
    if (!m_editor->points().empty())
        moveSceneTo(m_scene, m_model->t());
    updateReadout();
    updateCanvasSummary();
    if (isPlaying() || m_editor->dragging() || m_curveDrag->molding())
        schedulePanel(); // the triangle at t, a few times a second while t runs
    else
        updateExactPanel();
    m_canvas->update();
    emit tChanged(m_model->t());
}

double DeCasteljauTab::t() const { return m_model->t(); }

void DeCasteljauTab::setT(double t)
{
    m_model->setT(t); // comes back through tChanged
    m_parameter->setValue(m_model->t());
}

void DeCasteljauTab::setView(const DeCasteljauView& view)
{
    const DeCasteljauView v = view.clamped();
    const bool changed = v != m_view;
    m_view = v;
    showView();
    if (changed)
        pointsChanged(); // recomputes what the view needs (step curves, split list in the panel)
}

void DeCasteljauTab::showView()
{
    for (const Toggle& toggle : toggles())
        if (toggle.box->isChecked() != m_view.*toggle.flag) {
            const QSignalBlocker block(toggle.box);
            toggle.box->setChecked(m_view.*toggle.flag);
        }
    if (m_samplesBox->value() != m_view.samples) {
        const QSignalBlocker block(m_samplesBox);
        m_samplesBox->setValue(m_view.samples);
    }
    if (m_combScaleBox->value() != m_view.combScale)
        m_combScaleBox->setScale(m_view.combScale);
    m_editor->setHandlesVisible(m_view.controlPoints);
    m_editor->setSnapEnabled(m_view.snap);
}

void DeCasteljauTab::setFlag(bool DeCasteljauView::*flag, bool on)
{
    DeCasteljauView v = m_view;
    v.*flag = on;
    setView(v);
}

void DeCasteljauTab::setSamples(int part)
{
    DeCasteljauView v = m_view;
    v.samples = part;
    setView(v);
}

void DeCasteljauTab::setCombScale(double scale)
{
    DeCasteljauView v = m_view;
    v.combScale = scale;
    setView(v);
}

void DeCasteljauTab::pushT(double before, int mergeId, const QString& undoText)
{
    if (before == m_model->t())
        return;
    m_model->pushT(before, mergeId, undoText);
    emit documentChanged();
}

void DeCasteljauTab::userMovedT(double t)
{
    const double before = m_model->t();
    m_model->setT(t);
    if (!isPlaying()) // while playing, Pause makes the step
        pushT(before, m_parameter->gestureMergeId(), tr("Move t"));
}

void DeCasteljauTab::userChangedView(const DeCasteljauView& after, const QString& undoText, int mergeId)
{
    const DeCasteljauView before = m_view;
    setView(after);
    if (m_view == before)
        return;
    auto apply = [this](const DeCasteljauView& v) {
        setView(v);
        emit documentChanged();
    };
    m_undo->push(new ValueCommand<DeCasteljauView>(apply, before, m_view, undoText, mergeId,
                                                   {/*dropWhenUnchanged=*/true, /*appliedAlready=*/true}));
    emit documentChanged();
}

void DeCasteljauTab::setControlPointsVisible(bool on) { setFlag(&DeCasteljauView::controlPoints, on); }
void DeCasteljauTab::setConstructionVisible(bool on) { setFlag(&DeCasteljauView::construction, on); }
void DeCasteljauTab::setStepByStep(bool on) { setFlag(&DeCasteljauView::stepByStep, on); }
void DeCasteljauTab::setTangentVisible(bool on) { setFlag(&DeCasteljauView::tangent, on); }
void DeCasteljauTab::setSplitVisible(bool on) { setFlag(&DeCasteljauView::split, on); }
void DeCasteljauTab::setNormalVisible(bool on) { setFlag(&DeCasteljauView::normal, on); }
void DeCasteljauTab::setOsculatingCircleVisible(bool on) { setFlag(&DeCasteljauView::osculatingCircle, on); }
void DeCasteljauTab::setCombVisible(bool on) { setFlag(&DeCasteljauView::comb, on); }
void DeCasteljauTab::setBoundingBoxVisible(bool on) { setFlag(&DeCasteljauView::boundingBox, on); }
void DeCasteljauTab::setInflectionsVisible(bool on) { setFlag(&DeCasteljauView::inflections, on); }
void DeCasteljauTab::setHodographVisible(bool on) { setFlag(&DeCasteljauView::hodograph, on); }
void DeCasteljauTab::setConstantSpeed(bool on) { setFlag(&DeCasteljauView::constantSpeed, on); }

bool DeCasteljauTab::isPlaying() const { return m_timer->isActive(); }

void DeCasteljauTab::setPlaying(bool on)
{
    if (on && !m_timer->isActive()) {
        m_playStartT = m_model->t();
        m_timer->start();
    } else if (!on && m_timer->isActive()) {
        m_timer->stop();
        pushT(m_playStartT, -1, tr("Play t"));
    }
    if (m_play->isChecked() != on) {
        const QSignalBlocker block(m_play);
        m_play->setChecked(on);
    }
    m_play->setText(on ? tr("Pause") : tr("Play"));
    m_play->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void DeCasteljauTab::advanceAnimation()
{
    if (const auto& arc = m_scene.arc; m_view.constantSpeed && arc && arc->total() > 0) {
        // Equal steps of arc length: the point moves at constant speed, t does not.
        const double L = arc->total();
        const double s = arc->lengthAt(m_model->t()) + kAnimationStep * L;
        setT(s > L * (1.0 + 1e-12) ? 0.0 : arc->parameterAt(std::min(s, L)));
        return;
    }
    double t = m_model->t() + kAnimationStep;
    if (t > 1.0 + 1e-12)
        t = 0.0; // loops
    setT(std::min(t, 1.0));
}

void DeCasteljauTab::raiseDegree()
{
    const auto& points = m_editor->points();
    if (static_cast<int>(points.size()) >= kMaxPoints) {
        emit statusMessage(tr("At most %1 control points: the degree cannot be raised further.").arg(kMaxPoints));
        return;
    }
    // n + 1 control points make a curve of degree n; one point more is degree n + 1.
    const int raisedDegree = static_cast<int>(points.size());
    // Exact points are elevated exactly, so that the exact tables survive the step.
    const auto exact = m_editor->allExactPoints();
    if (exact) {
        const auto elevated = elevateDegree(*exact);
        m_editor->setPoints(toDouble(elevated), exactForms(elevated), tr("Raise degree to %1").arg(raisedDegree));
    } else {
        m_editor->setPoints(elevateDegree(points), tr("Raise degree to %1").arg(raisedDegree));
    }
    emit statusMessage(tr("Degree raised to %1: the same curve with one control point more.").arg(raisedDegree));
}

void DeCasteljauTab::updateWarning()
{
    const int n = static_cast<int>(m_editor->points().size()) - 1;
    const QString before = m_warningText;
    if (n >= kWarnDegree)
        m_warningText = tr("Degree %1 is high: in powers of t the condition number is %2, so only De Casteljau's "
                           "algorithm, which stays stable, is used here and the exact tables are hidden.")
                            .arg(n)
                            .arg(displaySignificant(powerBasisCondition(n), 2));
    else
        m_warningText.clear();
    m_warningLabel->setText(m_warningText);
    m_warningLabel->setVisible(!m_warningText.isEmpty());
    if (m_warningText != before && !m_warningText.isEmpty())
        emit statusMessage(m_warningText);
}

void DeCasteljauTab::updateExactSymbolic() { m_symbolicHtml = deCasteljauSymbolicHtml(m_scene.points, m_scene.exactPoints); }

void DeCasteljauTab::updateExactPanel()
{
    const auto& points = m_editor->points();
    if (points.empty() || m_scene.levels.levels.empty())
        return;
    DeCasteljauPanelInput in{points, m_model->t(), m_scene.levels, m_scene.curvature};
    in.exactPoints = m_scene.exactPoints;
    in.showSplit = m_view.split;
    if (m_scene.arc)
        in.arcLength = arcLengthAtT();
    in.totalLength = totalLength();
    in.curvatureReadout = readout().section(QStringLiteral(" · "), 1);
    in.symbolicHtml = m_symbolicHtml;
    in.warning = m_warningText;
    m_exact->setContent(deCasteljauPanelHtml(in));
}

QRectF DeCasteljauTab::contentBounds() const
{
    const std::optional<Aabb> box = finiteBox(m_editor->points());
    if (!box)
        return {-1, -1, 2, 2};
    double pad = 0.05 * std::max(box->width(), box->height());
    if (!(pad > 0))
        pad = 0.5 * std::max({std::fabs(box->minX), std::fabs(box->minY), 1e-9}); // one point, or all coincident
    return QRectF(QPointF(box->minX - pad, box->minY - pad), QPointF(box->maxX + pad, box->maxY + pad));
}

// ---------------------------------------------------------------- TabPage

void DeCasteljauTab::updateCanvasSummary()
{
    m_canvas->setAccessibleName(tr("De Casteljau canvas"));
    const auto& points = m_editor->points();
    if (points.empty() || m_scene.levels.levels.empty()) {
        m_canvas->setAccessibleDescription(tr("No control points."));
        return;
    }
    const Point c = m_scene.levels.point();
    m_canvas->setAccessibleDescription(
        tr("Bézier curve of degree %1 with %n control point(s); t = %2, c(t) = %3.", nullptr, static_cast<int>(points.size()))
            .arg(static_cast<int>(points.size()) - 1)
            .arg(displayNumber(m_model->t()), displayPoint(c.x, c.y)));
}

void DeCasteljauTab::retranslate()
{
    updateCanvasSummary();
    m_parameter->retranslate();
    setPlaying(isPlaying());                                // the button's text
    keepWidestTextWidth(m_play, {tr("Play"), tr("Pause")}); // one width, playing or not
    m_play->setToolTip(tr("Animate t from 0 to 1 and around again: watch c(t) trace the curve (Def 2.4)."));
    m_samplesLabel->setText(tr("Samples:"));
    const QString samplesTip = tr(
        "Sampling precision: the curve is drawn through this many intervals of t, like part in the thesis's Matlab "
        "De_Casteljau(P, part).");
    m_samplesLabel->setToolTip(samplesTip);
    m_samplesBox->setToolTip(samplesTip);
    m_raise->setText(tr("Raise degree"));
    m_raise->setToolTip(tr("Degree elevation: the same curve written with one control point more "
                           "(Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ). Undoable."));
    m_controlPoints->setText(tr("Control points"));
    m_controlPoints->setToolTip(tr("Draw the control points Pᵢ, their labels and the control polygon; off, the curve "
                                   "alone, like puntsvis = false in the thesis's Matlab. The table still edits the points."));
    m_construction->setText(tr("Construction"));
    m_construction->setToolTip(tr("Draw every level Pᵢʳ(t) of De Casteljau's algorithm (Def 2.4): the points of each "
                                  "level and the segments between them, one colour per level."));
    m_steps->setText(tr("Step by step"));
    m_steps->setToolTip(tr("Overlay the curves of the first 1, 2, …, n+1 control points, like the desglossar option of "
                           "the thesis's Matlab Rep_Bezier."));
    m_tangent->setText(tr("Tangent"));
    m_tangent->setToolTip(tr("The tangent vector c′(t) = n (P₁ⁿ⁻¹(t) − P₀ⁿ⁻¹(t)), read off the last level "
                             "but one of the construction; the arrow at c(t) is c′(t)/n, that last segment."));
    m_split->setText(tr("Split at t"));
    m_split->setToolTip(tr("Split the curve at t: the two edges of De Casteljau's triangle are the control polygons "
                           "of the halves [0, t] and [t, 1]."));
    m_normal->setText(tr("Normal"));
    m_normal->setToolTip(tr("The unit normal N(t) at c(t), the tangent turned a quarter turn to the left; drawn as long "
                            "as the tangent's arrow. Undefined where c′(t) = 0."));
    m_osculating->setText(tr("Osculating circle"));
    m_osculating->setToolTip(tr("The circle that fits the curve best at c(t): centre c(t) + N(t)/κ(t), radius 1/|κ(t)|. "
                                "None where κ = 0 (the radius is infinite) or where κ is undefined (c′(t) = 0)."));
    m_combBox->setText(tr("Curvature comb"));
    m_combBox->setToolTip(tr("Teeth along the normal, as long as |κ| times the scale given in the key, and the line "
                             "through their tips: where the comb jumps, so does the curvature. No tooth where κ is undefined."));
    m_combScaleLabel->setText(tr("scale:"));
    m_combScaleBox->retranslate();
    m_combScaleLabel->setToolTip(m_combScaleBox->toolTip());
    m_box->setText(tr("Bounding box"));
    m_box->setToolTip(tr("The tight axis-aligned box of the curve (not of its control points), from the extrema of x(t) "
                         "and y(t): the t where x′ = 0 or y′ = 0, marked ◆."));
    m_featuresBox->setText(tr("Inflections and cusps"));
    m_featuresBox->setToolTip(tr("Inflection points ○, where x′y″ − y′x″ changes sign (the curve turns the other way), "
                                 "and cusps ×, where c′ = 0."));
    m_hodograph->setText(tr("Hodograph"));
    m_hodograph->setToolTip(tr("The hodograph c′ in the corner: a Bézier curve of degree n − 1 with control points "
                               "n (Pᵢ₊₁ − Pᵢ), with its own De Casteljau construction at the same t; its point is c′(t)."));
    m_speed->setText(tr("Constant speed"));
    m_speed->setToolTip(tr("When playing, move c(t) by equal steps of arc length instead of equal steps of t: t is not "
                           "distance along the curve."));
    m_readout->setToolTip(tr("The arc length s(t) from c(0) to c(t), the curve's length L, and the signed curvature "
                             "κ(t) = (x′y″ − y′x″)/|c′|³ (positive when the curve turns left)."));
    updateReadout();
    m_snap->setText(tr("Snap to grid"));
    m_snap->setToolTip(tr("Round dragged and added points to the grid, so that they stay small fractions and the "
                          "exact tables appear."));
    m_canvas->setToolTip(
        tr("Control points P0…Pn of the Bézier curve (Def 2.4): drag a point, double-click to add "
           "one on the nearest edge, Delete removes the selected one, arrows nudge it. Drag the curve "
           "itself to mold it, or mold it at t with Alt+arrows; near the curve its closest point and t are shown."));
    m_exact->setToolTip(tr("De Casteljau's triangle Pᵢʳ(t) at the current t and, for rational points, every level "
                           "in powers of t, as in Ex 2.2 and Ex 2.3."));
    m_table->retranslate();
    updateWarning();
    updateExactSymbolic();
    updateExactPanel();
}

void DeCasteljauTab::writeSettings(QJsonObject& state) const
{
    state.insert(QStringLiteral("t"), m_model->t());
    writeDeCasteljauView(m_view, state);
}

PointListMessages DeCasteljauTab::pointMessages() const
{
    PointListMessages say;
    say.notAList = tr("The De Casteljau points are missing or not a list.");
    say.badCount = [](int count) {
        return tr("The De Casteljau tab needs between 1 and %1 control points; the document has %2.").arg(kMaxPoints).arg(count);
    };
    say.notAPair = [](int i) { return tr("Control point %1 is not a pair of finite numbers.").arg(i); };
    return say;
}

bool DeCasteljauTab::loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error)
{
    auto fail = [&error](const QString& message) {
        error = message;
        return false;
    };
    double t = 0.5;
    if (const QJsonValue v = state.value(QStringLiteral("t")); !v.isUndefined()) {
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < 0 || v.toDouble() > 1)
            return fail(tr("The parameter t must be a number between 0 and 1."));
        t = v.toDouble();
    }
    const std::optional<DeCasteljauView> view = readDeCasteljauView(state, error);
    if (!view)
        return false;

    m_playStartT = m_model->t(); // a document replaces t: stopping the animation is no step of its own
    setPlaying(false);
    m_view = *view;
    showView();
    const double before = m_model->t();
    m_model->setT(t);
    m_editor->applyPoints(points); // recomputes everything at the new t and view
    if (m_model->t() == before)
        emit tChanged(before); // once per document, as when t moves

    return true;
}

void DeCasteljauTab::loadCurve(const std::vector<Point>& points, const QString& undoText)
{
    m_model->loadCurve(points, undoText); // stops playing first, fits the view after
}

bool DeCasteljauTab::loadExample(const granota::WorkedExample& example)
{
    if (example.kind != "bezier" || example.points.empty())
        return false;
    const QString id = QString::fromStdString(example.id);
    m_model->loadCurve(example.points, tr("Load Ex %1").arg(id)); // stops playing first, fits the view after
    emit statusMessage(tr("Ex %1: the tables of the thesis are in the panel on the right at t = 1/2.").arg(id));
    return true;
}

QString DeCasteljauTab::csv() const
{
    QString out = QStringLiteral("i,x,y\n");
    const auto& points = m_editor->points();
    for (std::size_t i = 0; i < points.size(); ++i)
        out += QStringLiteral("%1,%2,%3\n")
                   .arg(i)
                   .arg(QString::fromStdString(readableExact(m_editor->exactAt(i).x, points[i].x)),
                        QString::fromStdString(readableExact(m_editor->exactAt(i).y, points[i].y)));
    out += QStringLiteral("\nt,x,y\n");
    const auto& curve = m_scene.curve;
    const double part = static_cast<double>(curve.size() > 1 ? curve.size() - 1 : 1);
    for (std::size_t j = 0; j < curve.size(); ++j)
        out += QStringLiteral("%1,%2,%3\n")
                   .arg(QString::fromStdString(formatReadable(static_cast<double>(j) / part)),
                        QString::fromStdString(formatReadable(curve[j].x)), QString::fromStdString(formatReadable(curve[j].y)));
    // The readouts at t (empty where undefined: a cusp has no curvature, a straight piece no radius).
    const auto f = [](double v) { return QString::fromStdString(formatReadable(v)); };
    const auto opt = [&f](const std::optional<double>& v) { return v ? f(*v) : QString(); };
    out += QStringLiteral("\nt,arc_length,length,curvature,radius\n");
    out += QStringLiteral("%1,%2,%3,%4,%5\n")
               .arg(f(m_model->t()), f(arcLengthAtT()), f(totalLength()), opt(m_scene.curvature.curvature),
                    opt(m_scene.curvature.radius));
    // The features of the curve (curve_features.h), whether or not they are drawn: each t
    // with its point, ascending within each kind.
    out += QStringLiteral("\nfeature,t,x,y\n");
    const bool finite = !points.empty() && std::all_of(points.begin(), points.end(), [](const Point& q) { return isFinite(q); });
    if (finite) {
        const CurveFeatures features = m_view.boundingBox || m_view.inflections ? m_scene.features : curveFeatures(points);
        const auto rows = [&](const char* kind, const std::vector<double>& ts) {
            for (double t : ts) {
                const Point c = deCasteljauPoint(points, t);
                out += QStringLiteral("%1,%2,%3,%4\n").arg(QLatin1String(kind), f(t), f(c.x), f(c.y));
            }
        };
        rows("extremum_x", features.extremaX);
        rows("extremum_y", features.extremaY);
        rows("inflection", features.inflections);
        rows("cusp", features.cusps);
    }
    return out;
}

void DeCasteljauTab::drawTikz(TikzWriter& w) const { writeDeCasteljauTikz(w, m_scene, contentBounds()); }

void DeCasteljauTab::presentationChanged(bool on)
{
    const int total = m_mainSplitter->width();
    if (total > 0) // the triangle's columns grow with the font: give the side panel half
        m_mainSplitter->setSizes({total * (on ? 50 : 62) / 100, total * (on ? 50 : 38) / 100});
    updateExactPanel();
}

QString DeCasteljauTab::hint() const
{
    return tr("Drag a point; double-click to add one; Delete removes the selected point; move t with the slider.");
}

} // namespace granota::ui
