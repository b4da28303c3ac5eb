#include "ui/bsplines/bspline_tab.h"

#include "core/base/number_format.h"
#include "core/io/worked_examples.h"
#include "ui/bsplines/bspline_basis_plot.h"
#include "ui/bsplines/bspline_curvature_plot.h"
#include "ui/bsplines/bspline_drawing.h"
#include "ui/bsplines/bspline_examples.h"
#include "ui/bsplines/bspline_report.h"
#include "ui/bsplines/knot_ruler.h"
#include "ui/bsplines/weight_gesture.h"
#include "ui/bsplines/weight_text.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/tab_order.h"
#include "ui/common/value_command.h"
#include "ui/common/vertical_scroll_area.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <optional>
#include <utility>

namespace granota::ui {

namespace {
/// Undo merge ids: the moves of one knot drag (one slider drag) share one, the next gesture has
/// the next; only consecutive steps merge, so the ids may wrap.
constexpr int kKnotMergeIdBase = 0x42530000; ///< "BS"
constexpr int kUMergeIdBase = 0x42550000;
constexpr int kGestureIds = 0x10000;
constexpr int kUSteps = 1000;      ///< slider steps over the domain [uₚ, uₙ₊₁]
constexpr int kPlaySteps = 200;    ///< Play moves u by 1/kPlaySteps of the domain a frame
constexpr int kAnimationMs = 40;   ///< Play's frame period (25 frames a second)
constexpr int kPresetItems = 4;    ///< clamped, uniform, Bézier, and "edited" (not a preset: shown only)
constexpr int kLongExactText = 14; ///< a fraction longer than this is shown as a decimal (u, the ruler)

constexpr int kBSplinePanelMs = 100; ///< exact panel refresh period while a point is dragged
} // namespace

BSplineTab::BSplineTab(QWidget* parent) : CurveTab(QStringLiteral("bspline"), QT_TR_NOOP("B-splines"), parent)
{
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& v, const CanvasStyle& s) {
        drawBSpline(p, v, s, m_model, m_scene, m_previousPolygon);
        if (m_editor && m_editor->handlesVisible())
            drawBSplineWeights(p, v, s, m_editor->points(), m_scene.exact.weights, m_editor->selected());
    });
    m_canvas->addOverlay([this](QPainter& p, const ViewTransform&, const CanvasStyle& s) {
        const QRectF inset = homogeneousInset();
        if (!inset.isEmpty())
            drawHomogeneousView(p, inset, m_scene.homogeneous, s, tr("The curve in (wx, wy, w)"));
    });
    m_editor = new PointEditor(m_canvas, m_undo, this);
    m_editor->setLabelPrefix(QStringLiteral("P"));
    m_editor->setCountLimits(2, BSplineModel::kMaxPoints);
    m_weightGesture = new WeightGesture(m_editor, this);
    connect(m_weightGesture, &WeightGesture::weightStepped, this, [this](int index, int steps) { stepWeight(index, steps); });
    m_timer = new QTimer(this);
    m_timer->setInterval(kAnimationMs);
    connect(m_timer, &QTimer::timeout, this, &BSplineTab::advanceAnimation);
    // While a point is dragged, the exact panel (a text document typeset again at every change,
    // the slowest part of a frame) follows every kBSplinePanelMs, as the De Casteljau tab's does,
    // and at once when the drag ends (bench_gui.cpp's BM_GuiBSplineDrag1000).
    m_panelTimer = new QTimer(this);
    m_panelTimer->setSingleShot(true);
    m_panelTimer->setInterval(kBSplinePanelMs);
    connect(m_panelTimer, &QTimer::timeout, this, [this] { m_exact->setContent(bsplineReportHtml(m_scene)); });
    buildUi();

    connect(m_editor, &PointEditor::pointsChanged, this, &BSplineTab::pointsEdited);
    connect(m_editor, &PointEditor::message, this, &BSplineTab::refuse);
    connect(m_table, &PointTable::message, this, &BSplineTab::refuse);

    // Start on a clamped cubic through six points: two interior knots, three spans to watch.
    const BSplineExample start = openingBSpline();
    m_editor->applyPoints(toDouble(start.curve.points));
    applyModel(start.model);
    retranslate();
    updateContentBounds(true);
}

// ---------------------------------------------------------------- widgets

void BSplineTab::buildUi()
{
    // Under the canvas: the knot ruler, u with Play, the basis functions.
    m_ruler = new KnotRuler(this);
    m_ruler->setObjectName(QStringLiteral("bsplineKnotRuler"));
    m_uLabel = new QLabel(this);
    m_uLabel->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("u = 0.0000000")));
    m_uSlider = new QSlider(Qt::Horizontal, this);
    m_uSlider->setRange(0, kUSteps);
    m_uSlider->setPageStep(kUSteps / 20);
    m_uLabel->setBuddy(m_uSlider);
    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("bsplinePlay"));
    m_play->setCheckable(true);
    m_play->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    auto* uRow = new QHBoxLayout;
    uRow->addWidget(m_uLabel);
    uRow->addWidget(m_uSlider, 1);
    uRow->addWidget(m_play);

    auto* plotBox = new QWidget(this);
    m_plotTitle = new QLabel(plotBox);
    m_plot = new QCustomPlot(plotBox);
    setUpBSplineBasisPlot(m_plot);
    auto* plotLayout = new QVBoxLayout(plotBox);
    plotLayout->setContentsMargins(0, 2, 0, 0);
    plotLayout->addWidget(m_plotTitle);
    plotLayout->addWidget(m_plot, 1);

    auto* under = new QWidget(this);
    auto* underLayout = new QVBoxLayout(under);
    underLayout->setContentsMargins(0, 0, 0, 0);
    underLayout->addWidget(m_ruler);
    underLayout->addLayout(uRow);
    underLayout->addWidget(plotBox, 1);

    connect(m_ruler, &KnotRuler::knotMoved, this, [this](int index, double value) {
        // At a neighbour the knot meets it exactly (2/3, not the round step nearest to its double).
        const std::vector<Rational> k = knots();
        const auto i = static_cast<std::size_t>(index);
        Rational v = rulerValue(value);
        if (index > 0 && value <= m_ruler->lowerBound(index))
            v = k[i - 1];
        else if (i + 1 < k.size() && value >= m_ruler->upperBound(index))
            v = k[i + 1];
        moveKnot(index, v, kKnotMergeIdBase + m_knotGesture % kGestureIds);
    });
    connect(m_ruler, &KnotRuler::dragFinished, this, [this] { ++m_knotGesture; });
    connect(m_ruler, &KnotRuler::insertRequested, this, [this](double value) { insertKnot(rulerValue(value)); });
    connect(m_ruler, &KnotRuler::insertAtParameterRequested, this, [this] { insertKnot(m_scene.u); });
    connect(m_ruler, &KnotRuler::removeRequested, this, [this](int index) { removeKnot(index); });
    connect(m_uSlider, &QSlider::valueChanged, this, [this](int k) {
        if (m_syncing || !m_scene.valid())
            return;
        const Rational lo = m_scene.exact.domainStart(), hi = m_scene.exact.domainEnd();
        setU(lo + (hi - lo) * frac(k, kUSteps), kUMergeIdBase + m_uGesture % kGestureIds);
    });
    connect(m_uSlider, &QSlider::sliderReleased, this, [this] { ++m_uGesture; });
    connect(m_play, &QToolButton::toggled, this, &BSplineTab::setPlaying);

    // The side panel: the curve, the actions, then the exact results and the points.
    m_curveBox = new QGroupBox(this);
    m_degreeLabel = new QLabel(m_curveBox);
    m_degreeSpin = new QSpinBox(m_curveBox);
    m_degreeSpin->setRange(1, kMaxBSplineDegree);
    m_degreeLabel->setBuddy(m_degreeSpin);
    m_presetLabel = new QLabel(m_curveBox);
    m_presetCombo = new QComboBox(m_curveBox);
    for (int i = 0; i < kPresetItems; ++i)
        m_presetCombo->addItem(QString());
    m_presetLabel->setBuddy(m_presetCombo);
    m_weightsLabel = new QLabel(m_curveBox);
    m_weightsEdit = new QLineEdit(m_curveBox);
    m_weightsEdit->setObjectName(QStringLiteral("bsplineWeights"));
    m_weightsLabel->setBuddy(m_weightsEdit);
    m_netCheck = new QCheckBox(m_curveBox);
    m_bezierCheck = new QCheckBox(m_curveBox);
    m_cubicCircleCheck = new QCheckBox(m_curveBox);
    m_curvatureCheck = new QCheckBox(m_curveBox);
    m_curvatureCheck->setObjectName(QStringLiteral("bsplineCurvaturePlot"));
    m_homogeneousCheck = new QCheckBox(m_curveBox);
    auto* curveLayout = new QGridLayout(m_curveBox);
    curveLayout->addWidget(m_degreeLabel, 0, 0);
    curveLayout->addWidget(m_degreeSpin, 0, 1);
    curveLayout->addWidget(m_presetLabel, 1, 0);
    curveLayout->addWidget(m_presetCombo, 1, 1);
    curveLayout->addWidget(m_weightsLabel, 2, 0);
    curveLayout->addWidget(m_weightsEdit, 2, 1);
    curveLayout->addWidget(m_netCheck, 3, 0, 1, 2);
    curveLayout->addWidget(m_bezierCheck, 4, 0, 1, 2);
    curveLayout->addWidget(m_cubicCircleCheck, 5, 0, 1, 2);
    curveLayout->addWidget(m_curvatureCheck, 6, 0, 1, 2);
    curveLayout->addWidget(m_homogeneousCheck, 7, 0, 1, 2);
    curveLayout->setColumnStretch(1, 1);
    connect(m_degreeSpin, &QSpinBox::valueChanged, this, [this](int d) {
        if (!m_syncing && !setDegree(d))
            syncControls();
    });
    connect(m_presetCombo, &QComboBox::activated, this, [this](int i) {
        if (m_syncing)
            return;
        if (i < 0 || i >= 3 || !setPreset(static_cast<KnotPreset>(i)))
            syncControls(); // "edited" is shown, not chosen
    });
    connect(m_weightsEdit, &QLineEdit::editingFinished, this, [this] {
        if (m_syncing)
            return;
        const auto w = parseTypedWeights(m_weightsEdit->text());
        if (!w) {
            refuse(tr("Weights are numbers separated by commas, such as 1, 1, 2 or 1, 1/2, 1; empty for none."));
            syncControls();
            return;
        }
        if (!setWeights(*w))
            syncControls();
    });
    connect(m_netCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setNetVisible(on);
    });
    connect(m_bezierCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setBezierSegmentsVisible(on);
    });
    connect(m_cubicCircleCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setCubicCircleVisible(on);
    });
    connect(m_curvatureCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setCurvaturePlot(on);
    });
    connect(m_homogeneousCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setHomogeneousCurveVisible(on);
    });

    m_actionsBox = new QGroupBox(this);
    m_insertButton = new QPushButton(m_actionsBox);
    m_removeButton = new QPushButton(m_actionsBox);
    m_elevateButton = new QPushButton(m_actionsBox);
    // A combo box rather than a button with a menu: its list does not run an event loop of its own.
    m_examplesCombo = new QComboBox(m_actionsBox);
    m_examplesCombo->setObjectName(QStringLiteral("bsplineExamples"));
    m_examplesCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_examplesCombo->setMinimumContentsLength(12);
    m_examplesCombo->addItem(QString()); // "Examples…": the prompt, not an example
    for (std::size_t i = 0; i < bsplineExampleIds().size(); ++i)
        m_examplesCombo->addItem(QString());
    auto* actionsLayout = new QGridLayout(m_actionsBox);
    actionsLayout->addWidget(m_insertButton, 0, 0);
    actionsLayout->addWidget(m_removeButton, 0, 1);
    actionsLayout->addWidget(m_elevateButton, 1, 0, 1, 2);
    actionsLayout->addWidget(m_examplesCombo, 2, 0, 1, 2);
    connect(m_insertButton, &QPushButton::clicked, this, [this] { insertKnot(m_scene.u); });
    connect(m_removeButton, &QPushButton::clicked, this, [this] {
        if (m_ruler->selected() < 0)
            refuse(tr("Select a knot on the ruler first (click it, or Left/Right while the ruler has the focus)."));
        else
            removeKnot(m_ruler->selected());
    });
    connect(m_elevateButton, &QPushButton::clicked, this, [this] { elevateDegree(); });
    connect(m_examplesCombo, &QComboBox::activated, this, [this](int i) {
        const std::vector<BSplineExampleId> ids = bsplineExampleIds();
        if (!m_syncing && i >= 1 && i <= static_cast<int>(ids.size()))
            loadBSplineExample(ids[static_cast<std::size_t>(i - 1)]);
        const QSignalBlocker block(m_examplesCombo);
        m_examplesCombo->setCurrentIndex(0); // back to the prompt
    });

    m_exact = new ExactPanel(this);
    m_table = new PointTable(m_editor, this);
    // The w column: each point's weight, typed as in the weights field (weight_text.h).
    m_table->setExtraColumn(
        QStringLiteral("w"), [this](int row) { return weightText(weightOf(row)); },
        [this](int row, const QString& text) {
            const auto w = parseTypedWeight(text);
            if (!w) {
                refuse(tr("“%1” is not a weight: type a decimal (0.7) or a fraction (3/2) greater than 0.").arg(text.trimmed()));
                return false;
            }
            return setWeight(row, *w);
        });
    m_sideTabs = new QTabWidget(this);
    m_sideTabs->addTab(m_exact, QString());
    m_sideTabs->addTab(m_table, QString());

    auto* controls = new QWidget;
    auto* controlsLayout = new QVBoxLayout(controls);
    controlsLayout->setContentsMargins(0, 0, 0, 0);
    controlsLayout->addWidget(m_curveBox);
    controlsLayout->addWidget(m_actionsBox);
    controlsLayout->addStretch(1);
    auto* scroll = new VerticalScrollArea(controls, this);

    auto* right = new QSplitter(Qt::Vertical, this);
    right->addWidget(scroll);
    right->addWidget(m_sideTabs);
    right->setStretchFactor(0, 0);
    right->setStretchFactor(1, 1);
    right->setSizes({340, 380}); // the controls whole at 1280 × 800 (the Examples box too)
    right->setChildrenCollapsible(false);

    auto* left = new QSplitter(Qt::Vertical, this);
    left->addWidget(m_canvas);
    left->addWidget(under);
    left->setStretchFactor(0, 3);
    left->setStretchFactor(1, 2);
    left->setSizes({480, 260});
    left->setChildrenCollapsible(false);

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(left);
    split->addWidget(right);
    setSidePanel(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setSizes({830, 420});
    split->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(split);

    setTabOrderOf({m_canvas, m_ruler, m_uSlider, m_play, m_plot, m_degreeSpin, m_presetCombo, m_weightsEdit, m_netCheck,
                   m_bezierCheck, m_cubicCircleCheck, m_curvatureCheck, m_homogeneousCheck, m_insertButton, m_removeButton,
                   m_elevateButton, m_examplesCombo, m_sideTabs});
}

QString BSplineTab::hint() const
{
    return tr("Drag a point; drag a knot on the ruler, double-click it to insert one; move u to follow de Boor's "
              "construction.");
}

QString BSplineTab::keyboardHint() const
{
    if (m_ruler && m_ruler->hasFocus())
        return tr("Ruler keys: Left/Right select a knot, Shift+Left/Right move it, Insert inserts a knot at u, Delete "
                  "removes the selected knot; Tab leaves the ruler.");
    return tr("Keys: ] and [ pick a point, arrows nudge it (Shift: ×10), + and − change its weight, Delete removes it; "
              "Tab leaves the canvas.");
}

void BSplineTab::retranslate()
{
    m_canvas->setAccessibleName(tr("B-spline canvas"));
    m_canvas->setToolTip(tr("Drag a point to move it; double-click to add one; Delete removes the selected point; "
                            "drag the paper to pan, wheel to zoom; Shift+wheel over a point changes its weight. The "
                            "ringed points are the p + 1 that act at u."));
    m_ruler->setAccessibleName(tr("Knot ruler"));
    m_ruler->setToolTip(tr("The knots u₀ ≤ … ≤ uₙ₊ₚ₊₁: drag one (it never passes its neighbours), double-click to "
                           "insert one, the badge is a knot's multiplicity. Bold: the domain [uₚ, uₙ₊₁]; yellow: the "
                           "span that holds u."));
    m_uSlider->setToolTip(tr("u in the domain [uₚ, uₙ₊₁]: the point c(u) and de Boor's net there."));
    m_uSlider->setAccessibleName(tr("Parameter u"));
    m_play->setToolTip(tr("Move u along the domain again and again; Pause makes it one undo step."));
    m_curveBox->setTitle(tr("B-spline"));
    m_degreeLabel->setText(tr("&Degree p:"));
    m_degreeSpin->setToolTip(tr("The degree of every piece, 1 to 10: the curve is Cᵖ⁻¹ at a simple knot. Needs at "
                                "least p + 1 points; the knots go back to the preset."));
    m_presetLabel->setText(tr("&Knots:"));
    m_presetCombo->setItemText(0, tr("clamped (open uniform)"));
    m_presetCombo->setItemText(1, tr("uniform"));
    m_presetCombo->setItemText(2, tr("Bézier (no interior knot)"));
    m_presetCombo->setItemText(3, tr("edited"));
    m_presetCombo->setToolTip(tr("Clamped: p + 1 equal knots at each end, the curve starts at P₀ and ends at Pₙ. "
                                 "Uniform: 0, 1, 2, …, the ends float. Bézier: no interior knot, degree n, exactly the "
                                 "Bézier curve of the points (Def 2.4). “Edited” is shown once a knot was moved or "
                                 "inserted."));
    m_weightsLabel->setText(tr("&Weights:"));
    m_weightsEdit->setPlaceholderText(tr("none (polynomial)"));
    m_weightsEdit->setToolTip(tr("One weight wᵢ > 0 per point, separated by commas (1, 1, 2): a rational B-spline "
                                 "(NURBS), c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ. Empty: polynomial."));
    m_netCheck->setText(tr("de Boor's &net at u"));
    m_netCheck->setToolTip(tr("de Boor's algorithm at u step by step: level r interpolates level r − 1, one colour per "
                              "level as in the De Casteljau tab, from the span's p + 1 points down to c(u)."));
    m_bezierCheck->setText(tr("Bé&zier segments"));
    m_bezierCheck->setToolTip(tr("Draw the control polygon of each Bézier segment of the curve (the knots inserted up to "
                                 "multiplicity p): one polynomial piece per span."));
    m_cubicCircleCheck->setText(tr("C&ubic Bézier circle beside"));
    m_cubicCircleCheck->setToolTip(tr("The usual cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3, "
                                      "dashed: close to the circle but not on it (its radial error is in the exact panel); "
                                      "the rational quarter circle is exact."));
    m_curvatureCheck->setText(tr("Curvature κ(s) in the &plot"));
    m_curvatureCheck->setToolTip(tr("Plot the signed curvature κ of the curve against its arc length s instead of the basis "
                                    "functions, each interior knot labelled with the continuity Cᵖ⁻ᵐ there: κ may jump "
                                    "at a knot of multiplicity p − 1 (C¹) and the curve may turn a corner at one of "
                                    "multiplicity p (C⁰)."));
    m_homogeneousCheck->setText(tr("Homo&geneous curve (wx, wy, w)"));
    m_homogeneousCheck->setToolTip(tr("An inset with the curve as the projection of a polynomial B-spline in space: the "
                                      "points Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) (purple), the polynomial curve through them, and the "
                                      "rays from the origin O through each Hᵢ down to the plane w = 1, where they meet "
                                      "Pᵢ and the rational curve."));
    m_actionsBox->setTitle(tr("Actions"));
    m_insertButton->setText(tr("&Insert knot at u"));
    m_insertButton->setToolTip(tr("Boehm's knot insertion: one more point and one more knot, the curve unchanged; the "
                                  "old polygon stays drawn dashed under the new one."));
    m_removeButton->setText(tr("&Remove knot"));
    m_removeButton->setToolTip(tr("Remove the knot selected on the ruler, only if the curve stays exactly the same."));
    m_elevateButton->setText(tr("&Elevate degree"));
    m_elevateButton->setToolTip(tr("Degree p + 1, the same curve: more points, each knot once more."));
    m_examplesCombo->setItemText(0, tr("Examples…"));
    for (std::size_t i = 0; i < bsplineExampleIds().size(); ++i)
        m_examplesCombo->setItemText(static_cast<int>(i) + 1, bsplineExampleTitle(bsplineExampleIds()[i]));
    m_examplesCombo->setAccessibleName(tr("Examples"));
    m_examplesCombo->setToolTip(tr("Ex 2.2's Bézier curve as a B-spline; a uniform cubic closed on Ex 2.13's points; the "
                                   "circle and the conics, exactly, as rational curves."));
    m_exact->setToolTip(tr("Exact results: de Boor's net at u, the basis functions there, their supports, the knots "
                           "with their multiplicities and the continuity of the curve at each."));
    m_sideTabs->setAccessibleName(tr("Exact results and points"));
    m_sideTabs->setTabText(0, tr("Exact results"));
    m_sideTabs->setTabText(1, tr("Points"));
    m_sideTabs->setTabToolTip(0, m_exact->toolTip());
    m_sideTabs->setTabToolTip(1, tr("The control points P0…Pn as numbers; fractions such as 1/3 are accepted."));
    m_table->setExtraColumnToolTip(tr("The weight wᵢ of each point (a rational B-spline when not all are 1)"));
    m_table->retranslate();
    setPlaying(isPlaying());
    syncControls();
    recompute();
}

void BSplineTab::syncControls()
{
    m_syncing = true;
    const int count = static_cast<int>(m_editor->points().size());
    m_degreeSpin->setValue(m_model.degreeFor(count));
    const bool edited = static_cast<int>(m_model.knots.size()) == count + m_model.degreeFor(count) + 1;
    m_presetCombo->setCurrentIndex(edited ? 3 : static_cast<int>(m_model.preset));
    QStringList w;
    for (const Rational& q : m_model.weightsFor(count))
        w << weightText(q);
    if (!m_weightsEdit->hasFocus())
        m_weightsEdit->setText(w.join(QStringLiteral(", ")));
    m_netCheck->setChecked(m_model.net);
    m_bezierCheck->setChecked(m_model.bezierSegments);
    m_cubicCircleCheck->setChecked(m_model.cubicCircle);
    m_curvatureCheck->setChecked(m_model.curvaturePlot);
    m_homogeneousCheck->setChecked(m_model.homogeneousCurve);
    if (m_model.curvaturePlot)
        setBSplineCurvaturePlotTexts(m_plotTitle, m_plot);
    else
        setBSplineBasisPlotTexts(m_plotTitle, m_plot);
    if (m_scene.valid()) {
        const Rational lo = m_scene.exact.domainStart(), hi = m_scene.exact.domainEnd();
        m_uSlider->setValue(static_cast<int>(std::lround(toDouble((m_scene.u - lo) / (hi - lo)) * kUSteps)));
        const std::string exact = toString(m_scene.u);
        m_uLabel->setText(QStringLiteral("u = %1").arg(exact.size() <= kLongExactText ? displayText(exact)
                                                                                      : displayNumber(toDouble(m_scene.u))));
    }
    m_syncing = false;
}

// ---------------------------------------------------------------- computing and showing

std::vector<RPoint> BSplineTab::exactValues() const
{
    const auto& points = m_editor->points();
    std::vector<RPoint> out;
    out.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const ExactPoint& q = m_editor->exactAt(i);
        out.emplace_back(exactOr(q.x, points[i].x), exactOr(q.y, points[i].y));
    }
    return out;
}

void BSplineTab::recompute()
{
    // While Play runs, the scene is at Play's u; the model (the document) keeps its own until Pause.
    BSplineModel shown = m_model;
    if (m_playU)
        shown.u = *m_playU;
    m_scene = computeBSplineScene(m_editor->points(), exactValues(), m_editor->allExactPoints().has_value(), shown);
    // The ruler's labels are the exact knots, or decimals where a fraction would be long.
    QStringList texts;
    for (const Rational& k : m_scene.exact.knots) {
        const std::string exact = toString(k);
        texts << (exact.size() <= kLongExactText ? displayText(exact) : displayNumber(toDouble(k)));
    }
    m_ruler->setKnots(m_scene.curve.knots, m_scene.degree(), texts);
    m_ruler->setParameter(toDouble(m_scene.u), m_scene.valid() ? m_scene.span() : -1);
    if (m_editor->dragging()) {
        if (!m_panelTimer->isActive())
            m_panelTimer->start();
    } else {
        m_panelTimer->stop();
        m_exact->setContent(bsplineReportHtml(m_scene));
    }
    updatePlot();
    m_canvas->update();
    m_canvas->setAccessibleDescription(
        tr("B-spline of degree %1 with %n control point(s) and %2 knots.", nullptr, static_cast<int>(m_editor->points().size()))
            .arg(m_scene.degree())
            .arg(m_scene.curve.knots.size()));
    syncControls();
}

void BSplineTab::pointsEdited()
{
    m_previousPolygon.clear();
    recompute();
    updateContentBounds(false);
    emit documentChanged();
}

void BSplineTab::applyModel(const BSplineModel& m)
{
    m_model = m;
    m_previousPolygon.clear();
    recompute();
    m_table->refreshExtraColumn(); // the weights, as the field shows them (syncControls)
}

void BSplineTab::refuse(const QString& message)
{
    m_lastMessage = message;
    emit statusMessage(message);
}

QRectF BSplineTab::contentBounds() const { return bsplineContentBounds(m_editor->points(), m_scene); }

void BSplineTab::updateContentBounds(bool force)
{
    if (!force) {
        // Edits keep the view unless a point leaves it (never during a drag).
        if (QGuiApplication::mouseButtons() != Qt::NoButton)
            return;
        const QRectF visible = m_canvas->view().visibleModelRect();
        bool outside = false;
        for (const Point& p : m_editor->points())
            outside = outside || !visible.contains(QPointF(p.x, p.y));
        if (!outside)
            return;
    }
    m_canvas->setContentBounds(contentBounds());
}

void BSplineTab::updatePlot()
{
    if (m_model.curvaturePlot) {
        updateBSplineCurvaturePlot(m_plot, font(), m_scene, presentationScale(presentation()));
        invalidateBSplineBasisPlot(m_plot); // it drew over the basis functions
    } else
        updateBSplineBasisPlot(m_plot, font(), m_scene, presentationScale(presentation()));
}

QRectF BSplineTab::homogeneousInset() const
{
    if (!m_model.homogeneousCurve || !m_scene.valid())
        return {};
    // The lower right corner of the canvas.
    const QRectF r = m_canvas->rect();
    const double w = std::min(r.width() * 0.48, 480.0), h = std::min(r.height() * 0.52, 360.0);
    return QRectF(r.right() - w - 8, r.bottom() - h - 8, w, h);
}

bool BSplineTab::isPlaying() const { return m_timer->isActive(); }

void BSplineTab::setPlaying(bool on)
{
    if (on && !m_timer->isActive()) {
        m_playU = m_scene.u;
        m_timer->start();
    } else if (!on && m_timer->isActive()) {
        m_timer->stop();
        // The whole play is one undo step, from the model's u to where it paused. Until then the
        // document kept its u: an undo, a save or a tab switch during Play meets no hidden change.
        const std::optional<Rational> played = std::exchange(m_playU, std::nullopt);
        if (played && *played != m_model.u) {
            BSplineModel after = m_model;
            after.u = *played;
            changeModel(after, tr("Play u"));
        } else {
            recompute();
        }
    }
    if (m_play->isChecked() != on) {
        const QSignalBlocker block(m_play);
        m_play->setChecked(on);
    }
    m_play->setText(on ? tr("Pause") : tr("Play"));
    m_play->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void BSplineTab::advanceAnimation()
{
    if (!m_scene.valid())
        return setPlaying(false);
    const Rational lo = m_scene.exact.domainStart(), hi = m_scene.exact.domainEnd();
    Rational u = m_scene.u + (hi - lo) * frac(1, kPlaySteps);
    if (u > hi)
        u = lo; // loops
    m_playU = u;
    recompute();
}

// ---------------------------------------------------------------- examples, documents and exports

void BSplineTab::loadBSplineExample(BSplineExampleId id)
{
    if (const auto ex = bsplineExample(id)) {
        changeCurve(ex->curve, ex->model, tr("Load %1").arg(bsplineExampleTitle(id)));
        updateContentBounds(true);
        m_canvas->fitToContent();
    }
}

bool BSplineTab::loadExample(const WorkedExample& example)
{
    // A Bézier curve of the thesis (Def 2.4) is the B-spline of degree n with no interior knot.
    const int count = static_cast<int>(example.points.size());
    if (example.kind != "bezier" || count < 2 || count - 1 > kMaxBSplineDegree)
        return false;
    BSplineCurve<Rational> c;
    c.points = example.points;
    c.degree = count - 1;
    c.knots = presetKnots<Rational>(KnotPreset::Bezier, count, c.degree);
    BSplineModel after = m_model;
    after.degree = c.degree;
    after.preset = KnotPreset::Bezier;
    after.knots.clear();
    after.weights.clear();
    after.u = frac(1, 2);
    changeCurve(c, after, tr("Load Ex %1").arg(QString::fromStdString(example.id)));
    updateContentBounds(true);
    m_canvas->fitToContent();
    return true;
}


void BSplineTab::writeSettings(QJsonObject& state) const
{
    // What is in force for the points there are (the knots and weights of another count are not).
    const int count = static_cast<int>(m_editor->points().size());
    BSplineModel m = m_model;
    m.degree = m_model.degreeFor(count);
    if (static_cast<int>(m.knots.size()) != count + m.degree + 1)
        m.knots.clear();
    m.weights = m_model.weightsFor(count);
    m.u = m_model.uFor(count);
    writeModel(m, state);
}

PointListMessages BSplineTab::pointMessages() const
{
    PointListMessages say;
    say.notAList = tr("The B-spline's control points are missing or not a list.");
    say.badCount = [](int count) {
        return tr("A B-spline needs between 2 and %1 control points; the file has %2.").arg(BSplineModel::kMaxPoints).arg(count);
    };
    say.notAPair = [](int i) { return tr("Point %1 of the B-spline tab is not a pair of numbers.").arg(i); };
    say.notFinite = [](int i) { return tr("Point %1 of the B-spline tab is not a finite number.").arg(i); };
    return say;
}

bool BSplineTab::loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error)
{
    QString problem;
    const auto model = readModel(state, &problem);
    if (!model) {
        error = tr("The B-spline settings are not valid (“%1”).").arg(problem);
        return false;
    }
    const int count = static_cast<int>(points.size());
    // Knots or weights saved for another number of points would silently give way to the
    // preset: a document says what it means or is refused.
    QString fault;
    if (model->degree > count - 1)
        fault = tr("degree %1 needs at least %2 points").arg(model->degree).arg(model->degree + 1);
    else if (!model->knots.empty() && static_cast<int>(model->knots.size()) != count + model->degree + 1)
        fault = tr("%1 knots for %2 points of degree %3 (n + p + 2 = %4 are needed)")
                    .arg(model->knots.size())
                    .arg(count)
                    .arg(model->degree)
                    .arg(count + model->degree + 1);
    else if (!model->weights.empty() && static_cast<int>(model->weights.size()) != count)
        fault = tr("%1 weights for %2 points").arg(model->weights.size()).arg(count);
    else if (const Expected<void> ok = checkBSpline(model->curve(toRational(points))); !ok)
        fault = QString::fromStdString(ok.error().message);
    if (!fault.isEmpty()) {
        error = tr("The B-spline in the document is not valid: %1.").arg(fault);
        return false;
    }
    setPlaying(false);
    m_editor->applyPoints(points);
    applyModel(*model);
    return true;
}

QString BSplineTab::csv() const
{
    const auto number = [](double v) { return QString::fromStdString(formatReadable(v)); };
    const auto& points = m_editor->points();
    QString out = QStringLiteral("point,x,y,w\n");
    const auto& w = m_scene.exact.weights;
    for (std::size_t i = 0; i < points.size(); ++i)
        out += QStringLiteral("P%1,%2,%3,%4\n")
                   .arg(i)
                   .arg(QString::fromStdString(readableExact(m_editor->exactAt(i).x, points[i].x)),
                        QString::fromStdString(readableExact(m_editor->exactAt(i).y, points[i].y)),
                        i < w.size() ? QString::fromStdString(toString(w[i])) : QStringLiteral("1"));
    out += QStringLiteral("\nknot,u\n");
    for (std::size_t i = 0; i < m_scene.exact.knots.size(); ++i)
        out += QStringLiteral("u%1,%2\n").arg(i).arg(QString::fromStdString(toString(m_scene.exact.knots[i])));
    out += QStringLiteral("\nsample,x,y\n");
    for (std::size_t i = 0; i < m_scene.samples.size(); ++i)
        out += QStringLiteral("%1,%2,%3\n").arg(i).arg(number(m_scene.samples[i].x), number(m_scene.samples[i].y));
    return out;
}

void BSplineTab::drawTikz(TikzWriter& w) const { writeBSplineTikz(w, m_editor->points(), m_model, m_scene); }

void BSplineTab::presentationChanged(bool on)
{
    m_ruler->setStyleScale(presentationScale(on));
    updatePlot();
}

void BSplineTab::resizeEvent(QResizeEvent* event)
{
    CurveTab::resizeEvent(event);
    // The plot's legend needs a plot high enough for it (updateBSplineBasisPlot).
    QTimer::singleShot(0, this, [this] { updatePlot(); });
}

void BSplineTab::changeEvent(QEvent* event)
{
    CurveTab::changeEvent(event);
    if (event->type() == QEvent::FontChange && m_plot)
        updatePlot();
}

} // namespace granota::ui
