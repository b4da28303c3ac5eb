#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/common/number_text.h"

#include "core/base/aabb.h"
#include "core/base/math_constants.h"
#include "core/curves/bezier/bernstein_properties.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bezier/hodograph.h"
#include "core/exact/polynomial.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/exact/rational_approximation.h"
#include "core/io/worked_examples.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/curve_canvas.h"
#include "ui/decasteljau/decasteljau_construction_drawing.h"
#include "ui/decasteljau/decasteljau_curve_drag.h"
#include "ui/decasteljau/decasteljau_flow_layout.h"
#include "ui/decasteljau/decasteljau_parameter_control.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "ui/common/tab_order.h"
#include "ui/common/value_command.h"
#include "ui/common/widest_text_width.h"
#include "ui/shell/tikz_writer.h"

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

using RPoly = Polynomial<Rational>;

constexpr int kDefaultSamples = 200; ///< Matlab `part`: the curve through part + 1 points
constexpr int kMinSamples = 1;       ///< one interval: the chord P_0 P_n
constexpr int kMaxSamples = 5000;    ///< 200 points × 5000 samples: about 1e8 operations
constexpr double kStepBudget = 2e7;  ///< operations allowed for the step-by-step curves per update
constexpr int kMinStepSamples = 16;
constexpr int kAnimationMs = 30;             ///< timer period of the t animation
constexpr int kPanelMs = 100;                ///< exact panel refresh period while dragging or playing
constexpr double kAnimationStep = 0.004;     ///< t per tick: one sweep of [0, 1] in about 7.5 s
constexpr long kExactTDenominator = 16;      ///< t = p/q with q ≤ 16 gives the triangle in fractions
constexpr long kMaxShownDenominator = 10000; ///< larger denominators: the triangle at t in decimals
constexpr int kLevelsPerTable = 3;           ///< symbolic table columns per block, as the thesis prints them
constexpr int kNumericLevelsPerTable = 5;

constexpr int kCombSamples = 160;                    ///< teeth of the curvature comb
constexpr int kHodographSamples = 120;               ///< the hodograph's curve in its inset
constexpr int kCircleSegments = 96;                  ///< the osculating circle as a polygon (TikZ)
constexpr long kExactCurvatureDenominator = 1000000; ///< κ in fractions while they stay this small

const QColor kTangentColour(0x6a, 0x3d, 0x9a);
const QColor kNormalColour(0xb1, 0x59, 0x28);
const QColor kCircleColour(0x7b, 0x8d, 0x2a);
const QColor kBoxColour(0x5e, 0x6a, 0x78);
const QColor kExtremumEdge(0x1c, 0x2a, 0x33); ///< the edge of an extremum's ◆
const QColor kInflectionColour(0xd6, 0x27, 0x8b);
const QColor kCuspColour(0xc0, 0x20, 0x20);

/// Ex 2.2-like default: a cubic with four points.
std::vector<Point> defaultPoints() { return {{0, 0}, {1, 2}, {3, 2}, {4, 0}}; }


/// Whether every level P_i^r(t) and c′(t) fits in a double (Def 2.4): control points
/// near ±1e308 make n (P_1 − P_0) or a level overflow to inf, or inf − inf to NaN.
bool fitsInDoubles(const DeCasteljauTable<double>& table)
{
    for (const auto& level : table.levels)
        for (const Point& p : level)
            if (!isFinite(p))
                return false;
    return isFinite(table.tangent());
}

template <class P> QString joinPoints(const std::vector<P>& points)
{
    QStringList parts;
    for (const P& p : points)
        parts << panelPointText(p);
    return parts.join(QStringLiteral(", "));
}

/// P_i^r(t) as HTML.
QString levelName(const QString& i, const QString& r) { return QStringLiteral("P<sub>%1</sub><sup>%2</sup>(t)").arg(i, r); }

/// A polynomial pair in one unbroken line (the panel scrolls sideways instead).
QString unbrokenPolynomial(const std::string& text)
{
    return QStringLiteral("<span style=\"white-space:nowrap\">%1</span>").arg(ExactPanel::polynomialHtml(text));
}

/// The triangle laid out as the thesis does: one row per i, one column per level r, in
/// blocks of `perTable` levels; `cell(r, i)` gives the HTML of P_i^r.
template <class Cell> QString triangleHtml(int n, int lastLevel, int perTable, Cell cell)
{
    // The cells never break inside (white-space: nowrap): a wide table scrolls sideways.
    QString html;
    for (int r0 = 0; r0 <= lastLevel; r0 += perTable) {
        const int r1 = std::min(lastLevel, r0 + perTable - 1);
        html += QStringLiteral("<table border=\"1\" cellspacing=\"0\"><tr><th></th>");
        for (int r = r0; r <= r1; ++r)
            html += QStringLiteral("<th>%1</th>").arg(levelName(QStringLiteral("i"), QString::number(r)));
        html += QStringLiteral("</tr>");
        for (int i = 0; i <= n - r0; ++i) {
            html += QStringLiteral("<tr><td style=\"white-space:nowrap\">i = %1</td>").arg(i);
            for (int r = r0; r <= r1; ++r)
                html += QStringLiteral("<td style=\"white-space:nowrap\">%1</td>").arg(i <= n - r ? cell(r, i) : QString());
            html += QStringLiteral("</tr>");
        }
        html += QStringLiteral("</table><p></p>");
    }
    return html;
}

void drawArrow(QPainter& p, const QPointF& from, const QPointF& to, double head)
{
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1e-9)
        return;
    const QPointF u = d / len, n(-u.y(), u.x());
    QPolygonF tip;
    tip << to << to - head * u + 0.45 * head * n << to - head * u - 0.45 * head * n;
    p.setBrush(p.pen().color());
    p.drawPolygon(tip);
}

/// Text for TeX: its special characters written as TeX reads them literally.
QString texText(const QString& text)
{
    QString out;
    for (const QChar c : text) {
        if (c == QLatin1Char('\\'))
            out += QStringLiteral("\\textbackslash{}");
        else if (c == QLatin1Char('~'))
            out += QStringLiteral("\\textasciitilde{}");
        else if (c == QLatin1Char('^'))
            out += QStringLiteral("\\textasciicircum{}");
        else if (QStringLiteral("&%$#_{}").contains(c))
            out += QLatin1Char('\\') + QString(c);
        else
            out += c;
    }
    return out;
}

/// The halves of the split at t: [0, t] and [t, 1].
const QColor kSplitColours[2] = {QColor(0xc0, 0x39, 0x8b), QColor(0x1b, 0x9e, 0x77)};
/// At most this many lines of levels (or of step curves) in the legend; the rest is one line.
constexpr int kMaxLegendLines = 6;

std::optional<bool> optionalBool(const QJsonObject& state, const char* key, bool* ok)
{
    const QJsonValue v = state.value(QLatin1String(key));
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isBool()) {
        *ok = false;
        return std::nullopt;
    }
    return v.toBool();
}

} // namespace

DeCasteljauTab::DeCasteljauTab(QWidget* parent) : CurveTab(QStringLiteral("decasteljau"), QT_TR_NOOP("De Casteljau"), parent)
{
    buildLayers(); // under the handles: the editor adds its own layer on top
    m_editor = new PointEditor(m_canvas, m_undo, this);
    m_editor->setCountLimits(1, kMaxPoints);
    m_editor->setLabelPrefix(QStringLiteral("P"));
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
    m_samplesBox->setRange(kMinSamples, kMaxSamples);
    m_samplesBox->setValue(m_samples);
    m_samplesBox->setKeyboardTracking(false);
    m_samplesLabel->setBuddy(m_samplesBox);
    m_raise = new QPushButton(this);
    m_controlPoints = new QCheckBox(this);
    m_controlPoints->setChecked(m_showControlPoints);
    m_construction = new QCheckBox(this);
    m_construction->setChecked(m_showConstruction);
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
    connect(m_editor, &PointEditor::message, this, &TabPage::statusMessage);
    connect(m_table, &PointTable::message, this, &TabPage::statusMessage);
    connect(m_curveDrag, &DeCasteljauCurveDrag::message, this, &TabPage::statusMessage);
    m_curveDrag->setParameterSource([this] { return m_t; });
    connect(m_parameter, &DeCasteljauParameterControl::valueChanged, this, &DeCasteljauTab::userMovedT);
    connect(m_play, &QToolButton::toggled, this, &DeCasteljauTab::setPlaying);
    connect(m_timer, &QTimer::timeout, this, &DeCasteljauTab::advanceAnimation);
    connect(m_samplesBox, &QSpinBox::valueChanged, this, &DeCasteljauTab::userSetSamples);
    connect(m_combScaleBox, &QDoubleSpinBox::valueChanged, this, &DeCasteljauTab::userSetCombScale);
    connect(m_raise, &QPushButton::clicked, this, &DeCasteljauTab::raiseDegree);
    connect(m_controlPoints, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showControlPoints, m_controlPoints, on, tr("Control points")); });
    connect(m_construction, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showConstruction, m_construction, on, tr("Construction")); });
    connect(m_steps, &QCheckBox::toggled, this, [this](bool on) { userToggled(m_showSteps, m_steps, on, tr("Step by step")); });
    connect(m_tangent, &QCheckBox::toggled, this, [this](bool on) { userToggled(m_showTangent, m_tangent, on, tr("Tangent")); });
    connect(m_split, &QCheckBox::toggled, this, [this](bool on) { userToggled(m_showSplit, m_split, on, tr("Split at t")); });
    connect(m_normal, &QCheckBox::toggled, this, [this](bool on) { userToggled(m_showNormal, m_normal, on, tr("Normal")); });
    connect(m_osculating, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showOsculating, m_osculating, on, tr("Osculating circle")); });
    connect(m_combBox, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showComb, m_combBox, on, tr("Curvature comb")); });
    connect(m_box, &QCheckBox::toggled, this, [this](bool on) { userToggled(m_showBox, m_box, on, tr("Bounding box")); });
    connect(m_featuresBox, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showFeatures, m_featuresBox, on, tr("Inflections and cusps")); });
    connect(m_hodograph, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_showHodograph, m_hodograph, on, tr("Hodograph")); });
    connect(m_speed, &QCheckBox::toggled, this,
            [this](bool on) { userToggled(m_constantSpeed, m_speed, on, tr("Constant speed")); });
    connect(m_snap, &QCheckBox::toggled, this, [this](bool on) {
        auto apply = [this](bool v) {
            const QSignalBlocker block(m_snap);
            m_snap->setChecked(v);
            m_editor->setSnapEnabled(v);
            emit documentChanged();
        };
        m_undo->push(new ValueCommand<bool>(apply, !on, on, tr("Snap to grid")));
    });

    m_editor->applyPoints(defaultPoints());
    m_parameter->setValue(m_t);
    m_canvas->setContentBounds(contentBounds());
    retranslate();
}

// ---------------------------------------------------------------- drawing

void DeCasteljauTab::buildLayers()
{
    // Rep_Bezier with desglossar: the curves of the first 1, 2, …, n + 1 points.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showSteps)
            return;
        p.setBrush(Qt::NoBrush);
        for (std::size_t k = 0; k < m_stepCurves.size(); ++k) {
            QColor c = CanvasStyle::series(static_cast<int>(k));
            c.setAlpha(170);
            p.setPen(QPen(c, style.lineWidth() * 0.75));
            if (m_stepCurves[k].size() == 1) {
                p.setBrush(c);
                p.drawEllipse(view.toScreen(m_stepCurves[k][0]), style.handleRadius() * 0.5, style.handleRadius() * 0.5);
                p.setBrush(Qt::NoBrush);
            } else {
                p.drawPath(polylinePath(m_stepCurves[k], view));
            }
        }
    });
    // The curve: all of it lighter, the part traced so far (0..t) bold.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_curve.size() < 2)
            return;
        p.setBrush(Qt::NoBrush);
        QColor light = style.curve;
        light.setAlpha(110);
        p.setPen(QPen(light, style.lineWidth(), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(polylinePath(m_curve, view));
        std::vector<Point> traced;
        const double part = static_cast<double>(m_curve.size() - 1);
        for (std::size_t j = 0; j < m_curve.size() && static_cast<double>(j) / part <= m_t; ++j)
            traced.push_back(m_curve[j]);
        if (!m_levels.levels.empty())
            traced.push_back(m_levels.point());
        p.setPen(QPen(style.curve, style.lineWidth() * 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(polylinePath(traced, view));
    });
    // The curvature comb (beyond the thesis), under the construction.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_showComb)
            drawCurvatureComb(p, view, style, m_comb);
    });
    // The tight bounding box and the extrema of x (◇ on its left and right sides) and y (on top and bottom).
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showBox || m_editor->points().empty())
            return;
        const Aabb& box = m_features.bbox;
        if (!isFinite(box.minCorner()) || !isFinite(box.maxCorner()))
            return;
        p.setPen(QPen(kBoxColour, style.thinLine() * 1.3, Qt::DashDotLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(view.toScreen(box.minCorner()), view.toScreen(box.maxCorner())).normalized());
        // Large, with a dark edge of the canvas's line width: a white 1 px edge round a slate
        // diamond of 9 px was lost on a projector (issue 34).
        const double r = style.handleRadius();
        p.setPen(QPen(kExtremumEdge, style.lineWidth(), Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
        p.setBrush(kBoxColour);
        const auto& points = m_editor->points();
        for (const auto* list : {&m_features.extremaX, &m_features.extremaY})
            for (double t : *list) {
                const QPointF c = view.toScreen(deCasteljauPoint(points, t));
                QPolygonF diamond;
                diamond << c + QPointF(0, -r) << c + QPointF(r, 0) << c + QPointF(0, r) << c + QPointF(-r, 0);
                p.drawPolygon(diamond);
            }
    });
    // The construction of Def 2.4: every level r ≥ 1, points and segments, one colour each.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_showConstruction && m_levels.levels.size() >= 2)
            drawDeCasteljauConstruction(p, view, style, m_levels);
    });
    // Split at t: the halves' control polygons are the triangle's two edges. Drawn over the
    // construction, on a white halo, with hollow squares larger than the level's dots: both
    // the halves and the construction under them stay visible.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showSplit || m_levels.levels.size() < 2)
            return;
        const std::vector<Point> halves[2] = {m_levels.leftHalf(), m_levels.rightHalf()};
        p.setBrush(Qt::NoBrush);
        for (int h = 0; h < 2; ++h) {
            const QPainterPath path = polylinePath(halves[h], view);
            p.setPen(QPen(QColor(255, 255, 255, 200), style.lineWidth() * 2.6, Qt::SolidLine, Qt::RoundCap));
            p.drawPath(path);
            p.setPen(QPen(kSplitColours[h], style.lineWidth() * 1.3, Qt::DashLine, Qt::RoundCap));
            p.drawPath(path);
            p.setPen(QPen(kSplitColours[h], style.thinLine() * 2));
            const double side = splitSquareSide(style);
            for (const Point& q : halves[h])
                p.drawRect(QRectF(view.toScreen(q) - QPointF(side, side) / 2, QSizeF(side, side)));
        }
    });
    // Inflections (hollow circles) and cusps (crosses).
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showFeatures || m_editor->points().empty())
            return;
        const auto& points = m_editor->points();
        const double r = style.handleRadius() * 1.1;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(kInflectionColour, style.thinLine() * 2.2));
        for (double t : m_features.inflections)
            p.drawEllipse(view.toScreen(deCasteljauPoint(points, t)), r, r);
        p.setPen(QPen(kCuspColour, style.thinLine() * 2.5, Qt::SolidLine, Qt::RoundCap));
        for (double t : m_features.cusps) {
            const QPointF c = view.toScreen(deCasteljauPoint(points, t));
            p.drawLine(c + QPointF(-r, -r), c + QPointF(r, r));
            p.drawLine(c + QPointF(-r, r), c + QPointF(r, -r));
        }
    });
    // The osculating circle at t: centre c(t) + N/κ, radius 1/|κ| (none where κ is 0 or undefined).
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showOsculating || !m_curvature.center || !m_curvature.radius)
            return;
        const QPointF c = view.toScreen(*m_curvature.center);
        const double r = *m_curvature.radius * view.scale();
        if (!std::isfinite(r) || !std::isfinite(c.x()) || !std::isfinite(c.y()) || r > 1e7)
            return; // nearly straight: a circle larger than any screen
        p.setPen(QPen(kCircleColour, style.lineWidth() * 0.8));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(c, r, r);
        p.setPen(QPen(kCircleColour, style.thinLine(), Qt::DotLine));
        p.drawLine(c, view.toScreen(m_curvature.point));
        p.setPen(QPen(Qt::white, style.thinLine()));
        p.setBrush(kCircleColour);
        p.drawEllipse(c, style.handleRadius() * 0.5, style.handleRadius() * 0.5);
    });
    // The unit normal N(t), left of the tangent, drawn as long as the tangent's arrow c′(t)/n.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showNormal || !m_curvature.normal || m_levels.degree() < 1)
            return;
        const double length = std::hypot(m_curvature.tangent.x, m_curvature.tangent.y) / m_levels.degree();
        const Point c = m_curvature.point, d = length * *m_curvature.normal;
        if (!isFinite(c) || !isFinite(d))
            return;
        p.setPen(QPen(kNormalColour, style.lineWidth()));
        const QPointF from = view.toScreen(c), to = view.toScreen(c + d);
        drawArrow(p, from, to, 11.0 * style.scale);
        p.setFont(style.labelFont());
        p.setPen(kNormalColour);
        const QFontMetricsF fm(p.font());
        const QPointF dir = to - from;
        const double len = std::hypot(dir.x(), dir.y());
        QPointF at = to + (len > 0 ? dir / len * (8.0 * style.scale) : QPointF()) + QPointF(0, fm.ascent() / 2);
        if (dir.x() < 0)
            at.rx() -= fm.horizontalAdvance(QStringLiteral("N(t)"));
        p.drawText(at, QStringLiteral("N(t)"));
    });
    // The tangent c′(t), from the last level but one.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_showTangent || m_levels.degree() < 1)
            return;
        // Drawn as c′(t)/n = P_1^{n−1}(t) − P_0^{n−1}(t): the last segment of the construction,
        // so the arrow stays on screen (c′ itself is n times longer).
        const int n = m_levels.degree();
        const Point c = m_levels.point(), d = (1.0 / n) * m_levels.tangent();
        if (!isFinite(c) || !isFinite(d))
            return;
        const QColor colour = kTangentColour;
        p.setPen(QPen(colour, style.lineWidth()));
        const QPointF from = view.toScreen(c), to = view.toScreen(c + d);
        drawArrow(p, from, to, 11.0 * style.scale);
        p.setFont(style.labelFont());
        p.setPen(colour);
        // The label beyond the arrow's tip, on the side the arrow points to.
        const QString label = n == 1 ? QStringLiteral("c′(t)") : QStringLiteral("c′(t)/%1").arg(n);
        const QPointF dir = to - from;
        const double len = std::hypot(dir.x(), dir.y());
        const QPointF ahead = len > 0 ? dir / len * (8.0 * style.scale) : QPointF();
        const QFontMetricsF fm(p.font());
        QPointF at = to + ahead + QPointF(0, fm.ascent() / 2);
        if (dir.x() < 0)
            at.rx() -= fm.horizontalAdvance(label);
        p.drawText(at, label);
    });
    // c(t) itself, prominent.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_levels.levels.empty() || !isFinite(m_levels.point()))
            return;
        const QPointF s = view.toScreen(m_levels.point());
        const double r = style.handleRadius() * 1.25;
        p.setPen(QPen(Qt::white, style.thinLine() * 2));
        p.setBrush(style.curve);
        p.drawEllipse(s, r, r);
        p.setPen(style.curve);
        QFont f = style.labelFont();
        f.setBold(true);
        p.setFont(f);
        p.drawText(s + QPointF(r + 4 * style.scale, r + 12 * style.scale), QStringLiteral("c(t)"));
    });
    // Over everything, the handles and their labels too: the hodograph c′ in an inset of its
    // own, with its own construction at t, and the key to the colours (which level, which step
    // curve, which half) in the corner where it covers least.
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_showHodograph)
            drawHodographInset(p, view, style);
    });
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        drawCanvasLegend(p, view, style, legend(), legendBox(view, style));
    });
}

// ---------------------------------------------------------------- updates

double DeCasteljauTab::splitSquareSide(const CanvasStyle& style) { return style.handleRadius() * 1.2 + 6 * style.scale; }

CanvasLegend DeCasteljauTab::legend() const
{
    CanvasLegend legend;
    const int n = m_levels.degree();
    const auto lines = [&legend](int first, int last, const std::function<QString(int)>& text) {
        for (int r = first; r <= last; ++r) {
            if (r - first == kMaxLegendLines - 1 && r < last) {
                legend.entries.push_back(
                    {CanvasStyle::series(r), Qt::DotLine, tr("… %1 more, one colour each").arg(last - r + 1)});
                return;
            }
            legend.entries.push_back({CanvasStyle::series(r), Qt::SolidLine, text(r)});
        }
    };
    if (m_showConstruction && n >= 2)
        lines(1, n - 1,
              [](int r) { return tr("level %1: the points %2(t)").arg(r).arg(QStringLiteral("Pᵢ") + superscriptDigits(r)); });
    if (m_showSteps && !m_stepCurves.empty())
        lines(0, static_cast<int>(m_stepCurves.size()) - 1,
              [](int k) { return k == 0 ? tr("the point P₀ alone") : tr("the curve of P₀…P%1").arg(subscriptDigits(k)); });
    if (m_showSplit && n >= 1) {
        legend.entries.push_back({kSplitColours[0], Qt::DashLine, tr("polygon of the half on [0, t]")});
        legend.entries.push_back({kSplitColours[1], Qt::DashLine, tr("polygon of the half on [t, 1]")});
    }
    if (m_showTangent && n >= 1)
        legend.entries.push_back({kTangentColour, Qt::SolidLine, n == 1 ? tr("tangent c′(t)") : tr("tangent c′(t)/%1").arg(n)});
    if (m_showNormal && n >= 1)
        legend.entries.push_back(m_curvature.normal ? CanvasLegendEntry{kNormalColour, Qt::SolidLine, tr("unit normal N(t)")}
                                                    : CanvasLegendEntry{kNormalColour, Qt::NoPen, tr("no normal: c′(t) = 0")});
    if (m_showOsculating && n >= 1) {
        if (m_curvature.radius)
            legend.entries.push_back(
                {kCircleColour, Qt::SolidLine, tr("osculating circle, r = 1/|κ| = %1").arg(panelNumber(*m_curvature.radius))});
        else if (m_curvature.curvature)
            legend.entries.push_back({kCircleColour, Qt::NoPen, tr("no osculating circle: κ(t) = 0")});
        else
            legend.entries.push_back({kCircleColour, Qt::NoPen, tr("no osculating circle: κ undefined")});
    }
    if (m_showComb && n >= 1 && !m_comb.empty())
        legend.entries.push_back(
            {curvatureCombColor(), Qt::SolidLine, tr("curvature comb: teeth |κ| × %1").arg(panelNumber(m_comb.scale))});
    if (m_showBox && n >= 0)
        legend.entries.push_back({kBoxColour, Qt::DashDotLine, tr("bounding box, ◆ extrema of x and y")});
    if (m_showFeatures && n >= 1) {
        legend.entries.push_back(
            {kInflectionColour, Qt::SolidLine,
             tr("○ inflections: %1 · × cusps: %2").arg(m_features.inflections.size()).arg(m_features.cusps.size())});
    }
    return legend;
}

QRectF DeCasteljauTab::legendRect(const ViewTransform& view, const CanvasStyle& style) const
{
    return legendBox(view, style).box;
}

CanvasLegendBox DeCasteljauTab::legendBox(const ViewTransform& view, const CanvasStyle& style) const
{
    CanvasLegendObstacles avoid = drawnObstacles(view, style);
    if (const QRectF inset = hodographInset(view, style); !inset.isEmpty())
        avoid.keepClear.push_back(inset);
    return canvasLegendRect(view, style, legend(), avoid);
}

CanvasLegendObstacles DeCasteljauTab::drawnObstacles(const ViewTransform& view, const CanvasStyle& style) const
{
    CanvasLegendObstacles avoid;
    for (const Point& q : m_curve)
        avoid.points.push_back(view.toScreen(q));
    if (m_showConstruction)
        for (const auto& level : m_levels.levels)
            for (const Point& q : level)
                avoid.points.push_back(view.toScreen(q));
    // The handles and their labels (as the point editor draws them), c(t) and its label, the inset.
    const QFontMetricsF fm(style.labelFont());
    const double r = style.handleRadius() * 1.3;
    const auto& points = m_editor->points();
    const auto marked = [&](const Point& q, const QString& label) {
        const QPointF s = view.toScreen(q);
        const QRectF handle(s - QPointF(r, r), QSizeF(2 * r, 2 * r));
        const QRectF text(s.x() + r + 3 * style.scale, s.y() - r - fm.ascent(), fm.horizontalAdvance(label), fm.height());
        avoid.keepClear.push_back(handle.united(text));
    };
    for (std::size_t i = 0; m_showControlPoints && i < points.size(); ++i)
        marked(points[i], m_editor->labelPrefix() + QString::number(i));
    if (!m_levels.levels.empty()) {
        // c(t)'s label is below right of its dot.
        const QPointF s = view.toScreen(m_levels.point());
        avoid.keepClear.push_back(
            QRectF(s - QPointF(r, r),
                   QSizeF(2 * r + 4 * style.scale + fm.horizontalAdvance(QStringLiteral("c(t)")), 2 * r + 12 * style.scale)));
    }
    return avoid;
}

QRectF DeCasteljauTab::hodographInset(const ViewTransform& view, const CanvasStyle& style) const
{
    if (!m_showHodograph || m_hodoLevels.levels.empty())
        return {};
    const QRectF viewport = view.viewport();
    const double margin = 8 * style.scale;
    // A corner of the canvas, small enough to leave the curve its room (in presentation mode
    // too): the one that covers least of what is drawn, as the key chooses its place.
    const double w = std::min(viewport.width() * 0.3, 260.0 * style.scale);
    const double h = std::min(w * 0.75, viewport.height() * 0.32);
    const double left = viewport.left() + margin, right = viewport.right() - margin - w;
    const double top = viewport.top() + margin, bottom = viewport.bottom() - margin - h;
    const CanvasLegendObstacles avoid = drawnObstacles(view, style);
    QRectF best;
    double least = std::numeric_limits<double>::infinity();
    for (const QPointF& corner : {QPointF(right, bottom), QPointF(left, bottom), QPointF(right, top), QPointF(left, top)}) {
        const QRectF box(corner, QSizeF(w, h));
        if (const double cost = canvasCoverCost(box, avoid); cost < least) {
            least = cost;
            best = box;
        }
    }
    return best;
}

void DeCasteljauTab::drawHodographInset(QPainter& p, const ViewTransform& view, const CanvasStyle& style) const
{
    const QRectF inset = hodographInset(view, style);
    if (inset.isEmpty())
        return;
    p.setPen(QPen(style.gridMajor, style.thinLine()));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRoundedRect(inset, 4, 4);
    QFont font;
    font.setPointSizeF(font.pointSizeF() * 0.9);
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double pad = 6 * style.scale;
    const QString title = tr("hodograph c′");
    p.setPen(style.text);
    p.drawText(QRectF(inset.left() + pad, inset.top() + pad / 2, inset.width() - 2 * pad, fm.height()),
               Qt::AlignLeft | Qt::AlignVCenter, fm.elidedText(title, Qt::ElideRight, inset.width() - 2 * pad));
    // Its own view: the hodograph's control points and the origin, fitted into the inset.
    const QRectF area = inset.adjusted(pad, pad + fm.height(), -pad, -pad);
    const auto& H = m_hodoLevels.levels.front();
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    for (const Point& q : H) {
        if (!isFinite(q))
            return;
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    ViewTransform own;
    own.setViewport(area);
    const double span = std::max({x1 - x0, y1 - y0, 1e-9});
    own.fit(QRectF(QPointF(x0, y0), QPointF(x1, y1)).adjusted(-span * 0.05, -span * 0.05, span * 0.05, span * 0.05), 2.0);
    p.save();
    p.setClipRect(area, Qt::IntersectClip);
    // The axes through the origin: c′(t) is a vector from there.
    const QPointF origin = own.toScreen({0, 0});
    p.setPen(QPen(style.axis, style.thinLine()));
    p.drawLine(QPointF(area.left(), origin.y()), QPointF(area.right(), origin.y()));
    p.drawLine(QPointF(origin.x(), area.top()), QPointF(origin.x(), area.bottom()));
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(style.polygon, style.thinLine(), Qt::DashLine));
    p.drawPath(polylinePath(H, own));
    QColor light = style.curve;
    light.setAlpha(160);
    p.setPen(QPen(light, style.lineWidth() * 0.8));
    p.drawPath(polylinePath(m_hodoCurve, own));
    if (m_showConstruction)
        // In the small view a high degree's dots would only cover each other (and cost a frame).
        drawDeCasteljauConstruction(p, own, style, m_hodoLevels, m_hodoLevels.degree() > 10 ? 0.0 : 0.45);
    p.setPen(QPen(Qt::white, style.thinLine()));
    p.setBrush(style.handle);
    for (const Point& q : H)
        p.drawEllipse(own.toScreen(q), style.handleRadius() * 0.55, style.handleRadius() * 0.55);
    // c′(t) as the arrow from the origin, and the point itself.
    const Point d = m_hodoLevels.point();
    p.setPen(QPen(kTangentColour, style.thinLine() * 1.5));
    drawArrow(p, origin, own.toScreen(d), 8.0 * style.scale);
    p.setPen(QPen(Qt::white, style.thinLine()));
    p.setBrush(style.curve);
    p.drawEllipse(own.toScreen(d), style.handleRadius() * 0.8, style.handleRadius() * 0.8);
    p.restore();
}

void DeCasteljauTab::updateCurvatureAtT()
{
    const auto& points = m_editor->points();
    if (points.empty())
        return;
    m_curvature = curvatureAt(points, m_t);
    if (m_showHodograph) {
        const auto H = hodograph(points);
        m_hodoLevels = deCasteljau(H, m_t);
    }
}

void DeCasteljauTab::updateGeometry()
{
    const auto& points = m_editor->points();
    if (points.empty())
        return;
    bool finite = true;
    for (const Point& q : points)
        finite = finite && isFinite(q);
    m_combScaleBox->setEnabled(m_showComb);
    m_combScaleLabel->setEnabled(m_showComb);
    m_features = CurveFeatures{};
    m_comb = CurvatureComb{};
    m_hodoCurve.clear();
    m_hodoLevels = DeCasteljauTable<double>{};
    m_arc.reset();
    if (!finite)
        return;
    if (m_showBox || m_showFeatures)
        m_features = curveFeatures(points);
    if (m_showComb) {
        m_comb = curvatureComb(points, kCombSamples, m_combScale);
        if (m_combScale == 0)
            m_combScaleBox->setAutomaticScale(m_comb.scale);
    }
    if (m_showHodograph)
        m_hodoCurve = sampleBezier(hodograph(points), kHodographSamples + 1);
    m_arc.emplace(points);
    updateCurvatureAtT();
}

double DeCasteljauTab::arcLengthAtT() const { return m_arc ? m_arc->lengthAt(m_t) : 0.0; }
double DeCasteljauTab::totalLength() const { return m_arc ? m_arc->total() : 0.0; }

QString DeCasteljauTab::readout() const
{
    if (m_editor->points().empty() || !m_arc)
        return QString();
    const QString lengths = tr("s(t) = %1 of L = %2").arg(panelNumber(arcLengthAtT()), panelNumber(totalLength()));
    QString kappa;
    if (!m_curvature.curvature)
        kappa = tr("κ(t) undefined: c′(t) = 0 (a cusp, or coincident control points)");
    else if (*m_curvature.curvature == 0.0)
        kappa = tr("κ(t) = 0: straight here, the radius is infinite");
    else
        kappa = tr("κ(t) = %1 (radius %2)").arg(panelNumber(*m_curvature.curvature), panelNumber(m_curvature.radius.value_or(0)));
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
    const auto& points = m_editor->points();
    if (points.empty())
        return;
    m_curve = sampleBezier(points, m_samples + 1);
    m_stepCurves.clear();
    if (m_showSteps) {
        // n + 1 curves of 1…n + 1 points cost about n³/6 per sample: fewer samples at high degree.
        const double n = static_cast<double>(points.size());
        const int part = std::min(m_samples, std::max(kMinStepSamples, static_cast<int>(kStepBudget * 6.0 / (n * n * n))));
        for (std::size_t k = 1; k <= points.size(); ++k)
            m_stepCurves.push_back(
                k == 1 ? std::vector<Point>{points[0]}
                       : sampleBezier(std::vector<Point>(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(k)),
                                      part + 1));
    }
    m_levels = deCasteljau(points, m_t);
    updateGeometry();
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
    updateExactSymbolic();
    updateExactPanel();
    updateWarning();
}

void DeCasteljauTab::schedulePanel()
{
    if (!m_panelTimer->isActive())
        m_panelTimer->start();
}

void DeCasteljauTab::parameterChanged()
{
    if (!m_editor->points().empty())
        m_levels = deCasteljau(m_editor->points(), m_t);
    updateCurvatureAtT();
    updateReadout();
    updateCanvasSummary();
    if (isPlaying() || m_editor->dragging() || m_curveDrag->molding())
        schedulePanel(); // the triangle at t, a few times a second while t runs
    else
        updateExactPanel();
    m_canvas->update();
    emit tChanged(m_t);
}

void DeCasteljauTab::setT(double t)
{
    if (!std::isfinite(t))
        return;
    t = std::clamp(t, 0.0, 1.0);
    m_parameter->setValue(t);
    if (t == m_t)
        return;
    m_t = t;
    parameterChanged();
}

void DeCasteljauTab::setSamples(int part)
{
    part = std::clamp(part, kMinSamples, kMaxSamples);
    if (m_samplesBox->value() != part) {
        const QSignalBlocker block(m_samplesBox);
        m_samplesBox->setValue(part);
    }
    if (part == m_samples)
        return;
    m_samples = part;
    pointsChanged();
}

void DeCasteljauTab::setToggle(bool& flag, QCheckBox* box, bool on)
{
    if (box->isChecked() != on) {
        const QSignalBlocker block(box);
        box->setChecked(on);
    }
    if (flag == on)
        return;
    flag = on;
    m_editor->setHandlesVisible(m_showControlPoints);
    pointsChanged(); // recomputes what the toggle needs (step curves, split list in the panel)
}

void DeCasteljauTab::pushT(double before, double after, int mergeId, const QString& undoText)
{
    if (before == after)
        return;
    auto apply = [this](double v) {
        setT(v);
        emit documentChanged();
    };
    m_undo->push(
        new ValueCommand<double>(apply, before, after, undoText, mergeId, {/*dropWhenUnchanged=*/true, /*appliedAlready=*/true}));
    emit documentChanged();
}

void DeCasteljauTab::userMovedT(double t)
{
    const double before = m_t;
    m_t = t;
    parameterChanged();
    if (!isPlaying()) // while playing, Pause makes the step
        pushT(before, m_t, m_parameter->gestureMergeId(), tr("Move t"));
}

void DeCasteljauTab::userToggled(bool& flag, QCheckBox* box, bool on, const QString& undoText)
{
    if (flag == on)
        return;
    auto apply = [this, &flag, box](bool v) {
        setToggle(flag, box, v);
        emit documentChanged();
    };
    setToggle(flag, box, on);
    m_undo->push(new ValueCommand<bool>(apply, !on, on, undoText, -1, {false, /*appliedAlready=*/true}));
    emit documentChanged();
}

void DeCasteljauTab::userSetSamples(int part)
{
    const int before = m_samples;
    setSamples(part);
    if (m_samples == before)
        return;
    auto apply = [this](int v) {
        setSamples(v);
        emit documentChanged();
    };
    constexpr int kSamplesMergeId = 0x44430001; // "DC": a spin box held down is one step
    m_undo->push(
        new ValueCommand<int>(apply, before, m_samples, tr("Samples: %1").arg(m_samples), kSamplesMergeId, {true, true}));
    emit documentChanged();
}

void DeCasteljauTab::setCombScale(double scale)
{
    scale = std::isfinite(scale) ? std::clamp(scale, 0.0, CurvatureCombScaleBox::kMaxScale) : 0.0;
    m_combScaleBox->setScale(scale);
    if (scale == m_combScale)
        return;
    m_combScale = scale;
    pointsChanged();
}

void DeCasteljauTab::userSetCombScale(double scale)
{
    const double before = m_combScale;
    setCombScale(scale);
    if (m_combScale == before)
        return;
    auto apply = [this](double v) {
        setCombScale(v);
        emit documentChanged();
    };
    constexpr int kCombScaleMergeId = 0x44430002; // "DC": a spin box held down is one step
    m_undo->push(new ValueCommand<double>(apply, before, m_combScale, tr("Comb scale"), kCombScaleMergeId, {true, true}));
    emit documentChanged();
}

void DeCasteljauTab::setControlPointsVisible(bool on) { setToggle(m_showControlPoints, m_controlPoints, on); }
void DeCasteljauTab::setConstructionVisible(bool on) { setToggle(m_showConstruction, m_construction, on); }
void DeCasteljauTab::setStepByStep(bool on) { setToggle(m_showSteps, m_steps, on); }
void DeCasteljauTab::setTangentVisible(bool on) { setToggle(m_showTangent, m_tangent, on); }
void DeCasteljauTab::setSplitVisible(bool on) { setToggle(m_showSplit, m_split, on); }
void DeCasteljauTab::setNormalVisible(bool on) { setToggle(m_showNormal, m_normal, on); }
void DeCasteljauTab::setOsculatingCircleVisible(bool on) { setToggle(m_showOsculating, m_osculating, on); }
void DeCasteljauTab::setCombVisible(bool on) { setToggle(m_showComb, m_combBox, on); }
void DeCasteljauTab::setBoundingBoxVisible(bool on) { setToggle(m_showBox, m_box, on); }
void DeCasteljauTab::setInflectionsVisible(bool on) { setToggle(m_showFeatures, m_featuresBox, on); }
void DeCasteljauTab::setHodographVisible(bool on) { setToggle(m_showHodograph, m_hodograph, on); }
void DeCasteljauTab::setConstantSpeed(bool on) { setToggle(m_constantSpeed, m_speed, on); }

bool DeCasteljauTab::isPlaying() const { return m_timer->isActive(); }

void DeCasteljauTab::setPlaying(bool on)
{
    if (on && !m_timer->isActive()) {
        m_playStartT = m_t;
        m_timer->start();
    } else if (!on && m_timer->isActive()) {
        m_timer->stop();
        pushT(m_playStartT, m_t, -1, tr("Play t"));
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
    if (m_constantSpeed && m_arc && m_arc->total() > 0) {
        // Equal steps of arc length: the point moves at constant speed, t does not.
        const double L = m_arc->total();
        const double s = m_arc->lengthAt(m_t) + kAnimationStep * L;
        setT(s > L * (1.0 + 1e-12) ? 0.0 : m_arc->parameterAt(std::min(s, L)));
        return;
    }
    double t = m_t + kAnimationStep;
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

void DeCasteljauTab::updateExactSymbolic()
{
    m_symbolicHtml.clear();
    const auto& points = m_editor->points();
    const int n = static_cast<int>(points.size()) - 1;
    const auto exact = m_editor->allExactPoints();
    if (!exact) {
        m_symbolicHtml = ExactPanel::note(tr("The exact polynomials need control points that are small fractions: "
                                             "type them in the table (1/3 is accepted) or turn on Snap to grid."));
        return;
    }
    if (n > kMaxExactDegree) {
        m_symbolicHtml = ExactPanel::note(tr("The levels in powers of t are shown up to degree %1; at degree %2 "
                                             "their coefficients would no longer be readable.")
                                              .arg(kMaxExactDegree)
                                              .arg(n));
        return;
    }
    // Def 2.4 run on polynomials: t is the polynomial t, every P_i^r(t) comes out expanded.
    std::vector<Vec2<RPoly>> symbolic;
    for (const RPoint& p : *exact)
        symbolic.emplace_back(RPoly(p.x), RPoly(p.y));
    const auto table = deCasteljau(symbolic, RPoly::identity());
    QString html = QStringLiteral("<h3>%1</h3>")
                       .arg(
                           tr("The levels %1 in powers of t (Def 2.4)").arg(levelName(QStringLiteral("i"), QStringLiteral("r"))));
    if (n >= 1)
        html += triangleHtml(n, n - 1, kLevelsPerTable, [&table](int r, int i) {
            return unbrokenPolynomial(toText(table.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]));
        });
    html += QStringLiteral("<p>%1 = c(t) = %2</p>")
                .arg(levelName(QStringLiteral("0"), QString::number(n)), unbrokenPolynomial(toText(table.point())));
    m_symbolicHtml = html;
}

void DeCasteljauTab::updateExactPanel()
{
    const auto& points = m_editor->points();
    if (points.empty() || m_levels.levels.empty())
        return;
    const int n = static_cast<int>(points.size()) - 1;
    const auto exactPoints = m_editor->allExactPoints();
    const auto exactT = smallRational(m_t, kExactTDenominator);
    QString html;
    std::optional<DeCasteljauTable<Rational>> exactTable;
    if (exactPoints && exactT && n <= kMaxExactDegree) {
        exactTable = deCasteljau(*exactPoints, *exactT);
        // Fractions only while they stay readable; decimals otherwise.
        bool readable = true;
        for (const auto& level : exactTable->levels)
            for (const RPoint& q : level)
                readable = readable && q.x.get_den() <= kMaxShownDenominator && q.y.get_den() <= kMaxShownDenominator;
        if (!readable)
            exactTable.reset();
    }
    if (exactTable) {
        // Rational points at a rational t: the triangle in fractions.
        const auto& table = *exactTable;
        html += ExactPanel::heading(
            tr("De Casteljau's triangle at t = %1 (Def 2.4)").arg(QString::fromStdString(toString(*exactT))));
        html += triangleHtml(n, n, kNumericLevelsPerTable, [&table](int r, int i) {
            return panelPointText(table.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]);
        });
        html += QStringLiteral("<p>c(t) = %1 = %2<br>c′(t) = %3</p>")
                    .arg(levelName(QStringLiteral("0"), QString::number(n)), panelPointText(table.point()),
                         panelPointText(table.tangent()));
        if (m_showSplit)
            html += QStringLiteral("<p>%1</p>")
                        .arg(tr("Split at t: [0, t] has control points %1; [t, 1] has %2.")
                                 .arg(joinPoints(table.leftHalf()), joinPoints(table.rightHalf())));
    } else {
        const QString tText = exactT ? QString::fromStdString(toString(*exactT)) : panelNumber(m_t);
        html += ExactPanel::heading(tr("De Casteljau's triangle at t = %1 (Def 2.4)").arg(tText));
        if (!fitsInDoubles(m_levels)) {
            // No wrong number: the values themselves do not exist in double precision.
            html += ExactPanel::note(tr("The values are too large for a double (beyond ±1.8e308): a level of the "
                                        "triangle or c′(t) overflows. Move the control points closer to the origin."));
            html += m_symbolicHtml;
            m_exact->setContent(html);
            return;
        }
        if (n <= kMaxTableDegree)
            html += triangleHtml(n, n, kNumericLevelsPerTable, [this](int r, int i) {
                return panelPointText(m_levels.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]);
            });
        else
            html += ExactPanel::note(
                tr("The triangle is shown up to degree %1; this curve has degree %2.").arg(kMaxTableDegree).arg(n));
        // c′(t) from the triangle, unless its doubles could not tell it from 0 and the exact
        // control points gave it (curvature.h: near ±1e308 the triangle says (0, 0) for (21/4, 0)).
        html += QStringLiteral("<p>c(t) = %1 = %2<br>c′(t) = %3</p>")
                    .arg(levelName(QStringLiteral("0"), QString::number(n)), panelPointText(m_levels.point()),
                         panelPointText(m_curvature.exact ? m_curvature.tangent : m_levels.tangent()));
        if (m_showSplit && n <= kMaxTableDegree)
            html += QStringLiteral("<p>%1</p>")
                        .arg(tr("Split at t: [0, t] has control points %1; [t, 1] has %2.")
                                 .arg(joinPoints(m_levels.leftHalf()), joinPoints(m_levels.rightHalf())));
    }
    html += exactCurvatureHtml();
    html += m_symbolicHtml;
    if (!m_warningText.isEmpty())
        html += ExactPanel::note(m_warningText);
    m_exact->setContent(html);
}

QString DeCasteljauTab::exactCurvatureHtml() const
{
    const auto& points = m_editor->points();
    if (points.empty() || !m_arc)
        return QString();
    QString html = ExactPanel::heading(tr("Arc length and curvature at t"));
    html += QStringLiteral("<p>%1</p>").arg(tr("s(t) = %1, L = %2").arg(panelNumber(arcLengthAtT()), panelNumber(totalLength())));
    // κ = (x′y″ − y′x″)/|c′|³: exact as k/(d√d) with k and d = |c′|² fractions, for rational points and t.
    const int n = static_cast<int>(points.size()) - 1;
    const auto exactPoints = m_editor->allExactPoints();
    const auto exactT = smallRational(m_t, kExactTDenominator);
    std::optional<QString> exact;
    if (exactPoints && exactT && n >= 1 && n <= kMaxExactDegree) {
        const auto H = hodograph(*exactPoints);
        const RPoint d1 = deCasteljauPoint(H, *exactT), d2 = deCasteljauPoint(hodograph(H), *exactT);
        const ExactCurvature k = exactCurvatureAt(*exactPoints, *exactT);
        const auto small = [](const Rational& q) {
            return abs(q.get_num()) <= kExactCurvatureDenominator && q.get_den() <= kExactCurvatureDenominator;
        };
        const auto text = [](const Rational& q) { return QString::fromStdString(toString(q)); };
        if (k.speedSquared == 0)
            exact = tr("κ(t) is undefined: c′(t) = 0 (a cusp, or coincident control points), so there is no normal "
                       "and no osculating circle.");
        else if (small(k.numerator) && small(k.speedSquared))
            if (const auto value = exactCurvatureText(k))
                exact = tr("c′(t) = %1, c″(t) = %2<br>x′y″ − y′x″ = %3, |c′(t)|² = %4<br>κ(t) = (x′y″ − y′x″)/|c′|³ = %5 ≈ %6")
                            .arg(panelPointText(d1), panelPointText(d2), text(k.numerator), text(k.speedSquared),
                                 QString::fromStdString(*value),
                                 panelNumber(k.numerator.get_d() / std::pow(k.speedSquared.get_d(), 1.5)));
    }
    if (exact)
        html += QStringLiteral("<p>%1</p>").arg(*exact);
    else
        html += QStringLiteral("<p>%1</p>").arg(readout().section(QStringLiteral(" · "), 1));
    return html;
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
    if (points.empty() || m_levels.levels.empty()) {
        m_canvas->setAccessibleDescription(tr("No control points."));
        return;
    }
    const Point c = m_levels.point();
    m_canvas->setAccessibleDescription(
        tr("Bézier curve of degree %1 with %n control point(s); t = %2, c(t) = %3.", nullptr, static_cast<int>(points.size()))
            .arg(static_cast<int>(points.size()) - 1)
            .arg(displayNumber(m_t), displayPoint(c.x, c.y)));
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
    state.insert(QStringLiteral("t"), m_t);
    state.insert(QStringLiteral("samples"), m_samples);
    state.insert(QStringLiteral("control_points"), m_showControlPoints);
    state.insert(QStringLiteral("construction"), m_showConstruction);
    state.insert(QStringLiteral("stepByStep"), m_showSteps);
    state.insert(QStringLiteral("tangent"), m_showTangent);
    state.insert(QStringLiteral("split"), m_showSplit);
    state.insert(QStringLiteral("snap"), m_editor->snapEnabled());
    state.insert(QStringLiteral("normal"), m_showNormal);
    state.insert(QStringLiteral("osculatingCircle"), m_showOsculating);
    state.insert(QStringLiteral("curvatureComb"), m_showComb);
    state.insert(QStringLiteral("curvatureCombScale"), m_combScale);
    state.insert(QStringLiteral("boundingBox"), m_showBox);
    state.insert(QStringLiteral("inflections"), m_showFeatures);
    state.insert(QStringLiteral("hodograph"), m_showHodograph);
    state.insert(QStringLiteral("constantSpeed"), m_constantSpeed);
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
    int samples = kDefaultSamples;
    if (const QJsonValue v = state.value(QStringLiteral("samples")); !v.isUndefined()) {
        const double s = v.toDouble(-1);
        if (!v.isDouble() || s != std::floor(s) || s < kMinSamples || s > kMaxSamples)
            return fail(tr("The number of samples must be a whole number from %1 to %2.").arg(kMinSamples).arg(kMaxSamples));
        samples = static_cast<int>(s);
    }
    bool ok = true;
    const auto controlPoints = optionalBool(state, "control_points", &ok);
    const auto construction = optionalBool(state, "construction", &ok);
    const auto steps = optionalBool(state, "stepByStep", &ok);
    const auto tangent = optionalBool(state, "tangent", &ok);
    const auto split = optionalBool(state, "split", &ok);
    const auto snap = optionalBool(state, "snap", &ok);
    const auto normal = optionalBool(state, "normal", &ok);
    const auto osculating = optionalBool(state, "osculatingCircle", &ok);
    const auto comb = optionalBool(state, "curvatureComb", &ok);
    const auto box = optionalBool(state, "boundingBox", &ok);
    const auto inflections = optionalBool(state, "inflections", &ok);
    const auto hodographShown = optionalBool(state, "hodograph", &ok);
    const auto speed = optionalBool(state, "constantSpeed", &ok);
    if (!ok)
        return fail(tr("A De Casteljau display option is not true or false."));
    double combScale = 0; // older documents: automatic
    if (const QJsonValue v = state.value(QStringLiteral("curvatureCombScale")); !v.isUndefined()) {
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < 0 || v.toDouble() > CurvatureCombScaleBox::kMaxScale)
            return fail(tr("The comb's scale must be 0 (automatic) or a positive number up to %1.")
                            .arg(displayNumber(CurvatureCombScaleBox::kMaxScale)));
        combScale = v.toDouble();
    }

    m_playStartT = m_t; // a document replaces t: stopping the animation is no step of its own
    setPlaying(false);
    m_showControlPoints = controlPoints.value_or(true); // older documents: shown
    m_editor->setHandlesVisible(m_showControlPoints);
    m_showConstruction = construction.value_or(true);
    m_showSteps = steps.value_or(false);
    m_showTangent = tangent.value_or(false);
    m_showSplit = split.value_or(false);
    // Documents older than these overlays have none of their keys: all off.
    m_showNormal = normal.value_or(false);
    m_showOsculating = osculating.value_or(false);
    m_showComb = comb.value_or(false);
    m_showBox = box.value_or(false);
    m_showFeatures = inflections.value_or(false);
    m_showHodograph = hodographShown.value_or(false);
    m_constantSpeed = speed.value_or(false);
    for (auto [check, on] :
         {std::pair{m_controlPoints, m_showControlPoints}, std::pair{m_construction, m_showConstruction},
          std::pair{m_steps, m_showSteps}, std::pair{m_tangent, m_showTangent}, std::pair{m_split, m_showSplit},
          std::pair{m_normal, m_showNormal}, std::pair{m_osculating, m_showOsculating}, std::pair{m_combBox, m_showComb},
          std::pair{m_box, m_showBox}, std::pair{m_featuresBox, m_showFeatures}, std::pair{m_hodograph, m_showHodograph},
          std::pair{m_speed, m_constantSpeed}}) {
        const QSignalBlocker block(check);
        check->setChecked(on);
    }
    {
        const QSignalBlocker block(m_snap);
        m_snap->setChecked(snap.value_or(false));
        m_editor->setSnapEnabled(snap.value_or(false));
    }
    m_combScale = combScale;
    m_combScaleBox->setScale(combScale);
    m_samples = samples;
    {
        const QSignalBlocker block(m_samplesBox);
        m_samplesBox->setValue(samples);
    }
    m_t = t;
    m_parameter->setValue(t);
    m_editor->applyPoints(points); // recomputes everything at the new t and samples
    emit tChanged(m_t);
    return true;
}

void DeCasteljauTab::loadCurve(const std::vector<Point>& points, const QString& undoText)
{
    setPlaying(false);
    m_undo->beginMacro(undoText);
    m_editor->setPoints(points, undoText);
    const double before = m_t;
    setT(0.5);
    pushT(before, m_t, -1, undoText);
    m_undo->endMacro();
    fitView();
}

bool DeCasteljauTab::loadExample(const granota::WorkedExample& example)
{
    if (example.kind != "bezier" || example.points.empty())
        return false;
    const QString id = QString::fromStdString(example.id);
    loadCurve(toDouble(example.points), tr("Load Ex %1").arg(id));
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
    const double part = static_cast<double>(m_curve.size() > 1 ? m_curve.size() - 1 : 1);
    for (std::size_t j = 0; j < m_curve.size(); ++j)
        out += QStringLiteral("%1,%2,%3\n")
                   .arg(QString::fromStdString(formatReadable(static_cast<double>(j) / part)),
                        QString::fromStdString(formatReadable(m_curve[j].x)),
                        QString::fromStdString(formatReadable(m_curve[j].y)));
    // The readouts at t (empty where undefined: a cusp has no curvature, a straight piece no radius).
    const auto f = [](double v) { return QString::fromStdString(formatReadable(v)); };
    const auto opt = [&f](const std::optional<double>& v) { return v ? f(*v) : QString(); };
    out += QStringLiteral("\nt,arc_length,length,curvature,radius\n");
    out += QStringLiteral("%1,%2,%3,%4,%5\n")
               .arg(f(m_t), f(arcLengthAtT()), f(totalLength()), opt(m_curvature.curvature), opt(m_curvature.radius));
    // The features of the curve (curve_features.h), whether or not they are drawn: each t
    // with its point, ascending within each kind.
    out += QStringLiteral("\nfeature,t,x,y\n");
    const bool finite = !points.empty() && std::all_of(points.begin(), points.end(), [](const Point& q) { return isFinite(q); });
    if (finite) {
        const CurveFeatures features = m_showBox || m_showFeatures ? m_features : curveFeatures(points);
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

void DeCasteljauTab::drawTikz(TikzWriter& w) const
{
    const CanvasStyle style;
    const auto& points = m_editor->points();
    w.comment(QStringLiteral("Bezier curve of degree %1 (De Casteljau, Def 2.4) at t = %2").arg(points.size() - 1).arg(m_t));
    if (m_showControlPoints)
        w.polyline(points, style.polygon, 0.6, true);
    if (m_showConstruction)
        for (int r = 1; r < m_levels.degree(); ++r)
            w.polyline(m_levels.levels[static_cast<std::size_t>(r)], CanvasStyle::series(r), 0.6);
    if (m_showComb) {
        for (const auto& tooth : m_comb.teeth)
            w.polyline({tooth.base, tooth.tip}, curvatureCombColor(), 0.3);
        for (const auto& stretch : m_comb.outline)
            w.polyline(stretch, curvatureCombColor(), 0.6);
    }
    if (m_showBox && isFinite(m_features.bbox.minCorner()) && isFinite(m_features.bbox.maxCorner())) {
        const Aabb& b = m_features.bbox;
        w.comment(QStringLiteral("tight bounding box and the extrema of x and y"));
        w.polyline({b.minCorner(), {b.maxX, b.minY}, b.maxCorner(), {b.minX, b.maxY}}, kBoxColour, 0.6, true, true);
        for (const auto* list : {&m_features.extremaX, &m_features.extremaY})
            for (double t : *list)
                w.point(deCasteljauPoint(points, t), kBoxColour);
    }
    w.polyline(m_curve, style.curve, 1.2);
    if (m_showFeatures && !points.empty()) {
        for (double t : m_features.inflections)
            w.point(deCasteljauPoint(points, t), kInflectionColour, QStringLiteral("\\mathrm{infl.}"));
        for (double t : m_features.cusps)
            w.point(deCasteljauPoint(points, t), kCuspColour, QStringLiteral("\\mathrm{cusp}"));
    }
    const int n = m_levels.degree();
    // Arrows, as on the canvas: c′(t)/n and N(t) are vectors from c(t).
    if (m_showTangent && n >= 1 && isFinite(m_levels.point()) && isFinite(m_levels.tangent()))
        w.arrow(m_levels.point(), m_levels.point() + (1.0 / n) * m_levels.tangent(), kTangentColour, 1.0);
    if (m_showNormal && n >= 1 && m_curvature.normal) {
        const double length = std::hypot(m_curvature.tangent.x, m_curvature.tangent.y) / n;
        const Point tip = m_curvature.point + length * *m_curvature.normal;
        if (isFinite(tip))
            w.arrow(m_curvature.point, tip, kNormalColour, 1.0);
    }
    const QRectF content = contentBounds();
    const double contentSize = std::max(content.width(), content.height());
    // A nearly straight piece has a circle far larger than the picture: it would shrink it to nothing.
    if (m_showOsculating && m_curvature.center && m_curvature.radius && isFinite(*m_curvature.center) &&
        *m_curvature.radius <= 4 * contentSize) {
        std::vector<Point> circle;
        for (int k = 0; k < kCircleSegments; ++k) {
            const double a = 2 * kPi * k / kCircleSegments;
            circle.push_back(*m_curvature.center + *m_curvature.radius * Point(std::cos(a), std::sin(a)));
        }
        w.comment(
            QStringLiteral("osculating circle at t, radius %1").arg(QString::fromStdString(formatDouble(*m_curvature.radius))));
        w.polyline(circle, kCircleColour, 0.8, false, true);
    }
    for (std::size_t i = 0; m_showControlPoints && i < points.size(); ++i)
        w.point(points[i], style.handle, QStringLiteral("P_{%1}").arg(i));
    if (!m_levels.levels.empty())
        w.point(m_levels.point(), style.curve, QStringLiteral("c(t)"));
    if (m_showHodograph && !m_hodoLevels.levels.empty() && fitsInDoubles(m_hodoLevels)) {
        // The inset of the canvas: c′ with its control polygon, its curve, its construction at t
        // and c′(t) as the vector from the origin.
        const auto& H = m_hodoLevels.levels.front();
        const QString title = texText(tr("hodograph c′")).replace(QStringLiteral("c′"), QStringLiteral("$c'$"));
        w.beginInset(title);
        QStringList coordinates;
        for (const Point& q : H)
            coordinates << QStringLiteral("(%1, %2)")
                               .arg(QString::fromStdString(formatDouble(q.x)), QString::fromStdString(formatDouble(q.y)));
        w.comment(QStringLiteral("hodograph: control points n (P_{i+1} - P_i) = %1").arg(coordinates.join(QStringLiteral(", "))));
        w.polyline(H, style.polygon, 0.4, true);
        w.polyline(m_hodoCurve, style.curve, 0.8);
        if (m_showConstruction)
            for (int r = 1; r < m_hodoLevels.degree(); ++r)
                w.polyline(m_hodoLevels.levels[static_cast<std::size_t>(r)], CanvasStyle::series(r), 0.4);
        for (const Point& q : H)
            w.point(q, style.handle);
        w.arrow({0, 0}, m_hodoLevels.point(), kTangentColour, 0.8);
        w.point(m_hodoLevels.point(), style.curve, QStringLiteral("c'(t)"));
        w.endInset();
    }
    // The canvas's key, placed as it is: where it covers least, clear of the inset.
    const CanvasLegend key = legend();
    std::vector<TikzLegendEntry> entries;
    for (const CanvasLegendEntry& e : key.entries)
        entries.push_back({e.color, e.pen, TikzWriter::texText(e.text)});
    w.legend(entries, TikzWriter::texText(key.note), key.alertColor);
}

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
