#include "ui/catmull_rom/catmull_rom_tab.h"

#include "core/exact/rational_approximation.h"
#include "core/io/worked_examples.h"
#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/catmull_rom_plot.h"
#include "ui/catmull_rom/catmull_rom_report.h"
#include "ui/catmull_rom/family_panel.h"
#include "ui/catmull_rom/family_report.h"
#include "ui/catmull_rom/spline_family_panels.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_table.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/value_command.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include "ui/common/vertical_scroll_area.h"

#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QTabWidget>
#include <QUndoStack>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr int kSliderSteps = 20;               ///< slider units per unit of τ: steps of 0.05
constexpr int kTauListRows = 4;                ///< rows of the τ list, whatever their number (Ex 2.12 has 4 τ)
constexpr int kSliderMergeIdBase = 0x43520000; ///< "CR": the merge ids of the τ slider's moves

/// τ as Processing's curveTightness(s), s = 1 − 2τ, as a short fraction or decimal.
QString tightnessString(const Rational& tau)
{
    const double s = tauToCurveTightness(toDouble(tau));
    if (const auto q = smallRational(s))
        return QString::fromStdString(toString(*q));
    return displayNumber(s);
}

} // namespace

CatmullRomTab::CatmullRomTab(QWidget* parent) : CurveTab(QStringLiteral("catmull-rom"), QT_TR_NOOP("Catmull-Rom"), parent)
{
    // Curves under the handles, the legend on top.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& v, const CanvasStyle& s) {
        drawCatmullRomCurves(p, v, s, m_settings, m_scene);
    });
    m_editor = new PointEditor(m_canvas, m_undo, this);
    m_editor->setLabelPrefix(QStringLiteral("q"));
    m_editor->setCountLimits(2, CatmullRomSettings::kMaxPoints);
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& v, const CanvasStyle& s) { drawLegend(p, v, s); });
    buildUi();

    connect(m_editor, &PointEditor::pointsChanged, this, &CatmullRomTab::pointsEdited);
    connect(m_editor, &PointEditor::message, this, &CatmullRomTab::refuse);
    connect(m_table, &PointTable::message, this, &CatmullRomTab::refuse);

    // Start as Ex 2.11: its four points, τ ∈ {0, 1/2, 2}, open ends.
    std::vector<Point> start{{1, 1}, {3, 4}, {2, -1}, {5, 1}};
    if (const WorkedExample* ex = findWorkedExample("2.11"))
        start = toDouble(ex->points);
    m_editor->applyPoints(start);
    applySettings(CatmullRomSettings{});
    retranslate();
    updateContentBounds(true);
}

// ---------------------------------------------------------------- widgets

void CatmullRomTab::buildUi()
{
    buildFamilyControls();                         // the family selector, the chosen family's controls, the Hermite handles
    m_splinePanels = new SplineFamilyPanels(this); // the C² spline's and the function data's controls, in their families
    connect(m_splinePanels, &SplineFamilyPanels::changeRequested, this,
            [this](const CatmullRomSettings& after, const QString& text) { changeSettings(after, text); });
    connect(m_splinePanels, &SplineFamilyPanels::exampleRequested, this, &CatmullRomTab::loadPointsAndSettings);
    connect(m_splinePanels, &SplineFamilyPanels::refused, this, &CatmullRomTab::refuse);
    // Tensions.
    m_tensionBox = new QGroupBox(this);
    m_tauList = new QListWidget(m_tensionBox);
    m_tauList->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tauEdit = new QLineEdit(m_tensionBox);
    m_addTau = new QPushButton(m_tensionBox);
    m_removeTau = new QPushButton(m_tensionBox);
    m_tauSlider = new QSlider(Qt::Horizontal, m_tensionBox);
    m_tauSlider->setRange(-CatmullRomSettings::kMaxTensionAbs * kSliderSteps, CatmullRomSettings::kMaxTensionAbs * kSliderSteps);
    m_tauSlider->setPageStep(kSliderSteps / 2);
    m_sliderLabel = new QLabel(m_tensionBox);
    m_sliderLabel->setWordWrap(true);
    auto* tauLayout = new QGridLayout(m_tensionBox);
    tauLayout->addWidget(m_tauList, 0, 0, 1, 3);
    tauLayout->addWidget(m_tauEdit, 1, 0);
    tauLayout->addWidget(m_addTau, 1, 1);
    tauLayout->addWidget(m_removeTau, 1, 2);
    tauLayout->addWidget(m_sliderLabel, 2, 0, 1, 3);
    tauLayout->addWidget(m_tauSlider, 3, 0, 1, 3);
    tauLayout->setColumnStretch(0, 1);

    connect(m_addTau, &QPushButton::clicked, this, [this] {
        if (addTension(m_tauEdit->text()))
            m_tauEdit->clear();
    });
    connect(m_tauEdit, &QLineEdit::returnPressed, m_addTau, &QPushButton::click);
    connect(m_removeTau, &QPushButton::clicked, this, [this] { removeTension(m_settings.selectedTau); });
    connect(m_tauList, &QListWidget::currentRowChanged, this, [this](int row) {
        if (!m_syncing)
            setSelectedTension(row);
    });
    connect(m_tauSlider, &QSlider::valueChanged, this, [this](int value) {
        if (!m_syncing)
            sliderMoved(value);
    });

    // Curve options.
    m_curveBox = new QGroupBox(this);
    m_endsLabel = new QLabel(m_curveBox);
    m_endsCombo = new QComboBox(m_curveBox);
    m_spacingLabel = new QLabel(m_curveBox);
    m_spacingCombo = new QComboBox(m_curveBox);
    for (int i = 0; i < 4; ++i)
        m_endsCombo->addItem(QString());
    for (int i = 0; i < 3; ++i)
        m_spacingCombo->addItem(QString());
    m_endsLabel->setBuddy(m_endsCombo);
    m_spacingLabel->setBuddy(m_spacingCombo);
    m_bezierCheck = new QCheckBox(m_curveBox);
    m_splineCheck = new QCheckBox(m_curveBox);
    m_catmullRomCheck = new QCheckBox(m_curveBox);
    m_pointsCheck = new QCheckBox(m_curveBox);
    m_splineEndsLabel = new QLabel(m_curveBox);
    m_splineEndsCombo = new QComboBox(m_curveBox);
    for (int i = 0; i < 4; ++i)
        m_splineEndsCombo->addItem(QString());
    m_splineEndsLabel->setBuddy(m_splineEndsCombo);
    m_slopesLabel = new QLabel(m_curveBox);
    m_startSlopeEdit = new QLineEdit(m_curveBox);
    m_endSlopeEdit = new QLineEdit(m_curveBox);
    auto* slopes = new QHBoxLayout;
    slopes->addWidget(m_startSlopeEdit);
    slopes->addWidget(m_endSlopeEdit);
    m_slopesLabel->setBuddy(m_startSlopeEdit);
    m_compareCheck = new QCheckBox(m_curveBox);
    m_curvatureCheck = new QCheckBox(m_curveBox);
    auto* curveLayout = new QGridLayout(m_curveBox);
    curveLayout->addWidget(m_endsLabel, 0, 0);
    curveLayout->addWidget(m_endsCombo, 0, 1);
    curveLayout->addWidget(m_spacingLabel, 1, 0);
    curveLayout->addWidget(m_spacingCombo, 1, 1);
    // The points and the Catmull-Rom curves side by side: two short check boxes, one row.
    auto* shown = new QHBoxLayout;
    shown->addWidget(m_catmullRomCheck);
    shown->addWidget(m_pointsCheck);
    shown->addStretch(1);
    curveLayout->addLayout(shown, 2, 0, 1, 2);
    curveLayout->addWidget(m_bezierCheck, 3, 0, 1, 2);
    curveLayout->addWidget(m_splineCheck, 4, 0, 1, 2);
    // The spline's own rows, under its check box: their labels do not widen the first column.
    auto* splineEnds = new QHBoxLayout;
    splineEnds->addSpacing(20);
    splineEnds->addWidget(m_splineEndsLabel);
    splineEnds->addWidget(m_splineEndsCombo, 1);
    slopes->insertSpacing(0, 20);
    slopes->insertWidget(1, m_slopesLabel);
    curveLayout->addLayout(splineEnds, 5, 0, 1, 2);
    curveLayout->addLayout(slopes, 6, 0, 1, 2);
    curveLayout->addWidget(m_compareCheck, 7, 0, 1, 2);
    curveLayout->addWidget(m_curvatureCheck, 8, 0, 1, 2);
    connect(m_catmullRomCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setCatmullRomVisible(on);
    });
    connect(m_pointsCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setControlPointsVisible(on);
    });
    connect(m_splineEndsCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!m_syncing && i >= 0)
            setSplineEnds(static_cast<SplineEnds>(i));
    });
    const auto slopeTyped = [this] {
        if (m_syncing)
            return;
        const auto start = parseTension(m_startSlopeEdit->text()), end = parseTension(m_endSlopeEdit->text());
        if (!start || !end) {
            refuse(tr("An end slope is a number between −10 and 10, such as 1/2 or -0.25."));
            syncControls(); // back to the slopes in use
            return;
        }
        setSplineSlopes(*start, *end);
    };
    connect(m_startSlopeEdit, &QLineEdit::editingFinished, this, slopeTyped);
    connect(m_endSlopeEdit, &QLineEdit::editingFinished, this, slopeTyped);
    curveLayout->setColumnStretch(1, 1);
    connect(m_endsCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!m_syncing && i >= 0)
            setEnds(static_cast<CatmullRomEnds>(i));
    });
    connect(m_spacingCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (!m_syncing && i >= 0)
            setSpacing(static_cast<CatmullRomSpacing>(i));
    });
    connect(m_bezierCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setBezierVisible(on);
    });
    connect(m_splineCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setSplineVisible(on);
    });
    connect(m_compareCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setCompareEnds(on);
    });

    // Blending functions plot.
    auto* plotBox = new QWidget(this);
    m_plotTitle = new QLabel(plotBox);
    m_allTausCheck = new QCheckBox(plotBox);
    m_plot = new QCustomPlot(plotBox); // its minimum height follows its font (updatePlot)
    setUpCatmullRomPlot(m_plot);
    auto* plotHeader = new QHBoxLayout;
    plotHeader->addWidget(m_plotTitle, 1);
    plotHeader->addWidget(m_allTausCheck);
    auto* plotLayout = new QVBoxLayout(plotBox);
    plotLayout->setContentsMargins(0, 4, 0, 0);
    plotLayout->addLayout(plotHeader);
    plotLayout->addWidget(m_plot, 1);
    connect(m_allTausCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setAllTausInPlot(on);
    });
    connect(m_curvatureCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            setCurvaturePlot(on);
    });

    // Exact results and the points table.
    m_exact = new ExactPanel(this);
    m_table = new PointTable(m_editor, this);
    m_sideTabs = new QTabWidget(this);
    // The knot table and the conventions (catmull_rom_tab_families.cpp) added first, so that
    // among the children the points table still comes before them; shown after the two.
    addFamilySideTabs();
    m_sideTabs->insertTab(0, m_exact, QString());
    m_sideTabs->insertTab(1, m_table, QString());
    m_sideTabs->setCurrentIndex(0);

    auto* controls = new QWidget;
    auto* controlsLayout = new QVBoxLayout(controls);
    controlsLayout->setContentsMargins(0, 0, 0, 0);
    controlsLayout->addWidget(m_tensionBox);
    controlsLayout->addWidget(m_curveBox);
    controlsLayout->insertWidget(0, m_familyPanel); // on top, but after the others among the children (tests find the ends first)
    controlsLayout->insertWidget(1, m_splinePanels);
    controlsLayout->addStretch(1);
    auto* scroll = new VerticalScrollArea(controls, this); // Tab goes to its controls, and it scrolls to the one focused

    auto* right = new QSplitter(Qt::Vertical, this);
    right->addWidget(scroll);
    right->addWidget(m_sideTabs);
    right->setStretchFactor(0, 0);
    right->setStretchFactor(1, 1);
    right->setSizes({380, 340});
    right->setChildrenCollapsible(false);

    auto* left = new QSplitter(Qt::Vertical, this);
    left->addWidget(m_canvas);
    left->addWidget(plotBox);
    left->setStretchFactor(0, 3);
    left->setStretchFactor(1, 1);
    left->setSizes({520, 200});
    left->setChildrenCollapsible(false);

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(left);
    split->addWidget(right);
    setSidePanel(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setSizes({830, 450});
    split->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(split);
}

QString CatmullRomTab::hint() const
{
    return tr("Drag a point; double-click to add one; pick a τ in the list and move its slider, or type one and press Enter.");
}

void CatmullRomTab::retranslate()
{
    updateCanvasSummary();
    retranslateFamilyControls();
    m_splinePanels->retranslate();
    m_tensionBox->setTitle(tr("Tensions τ (Def 2.8)"));
    m_tensionBox->setToolTip(tr("The tension τ scales the tangents p′(0) = τ(p2 − p0), p′(1) = τ(p3 − p1) of every "
                                "segment (Def 2.8): 0 gives straight segments, 1/2 is the usual value, negative "
                                "values turn the tangents round (Ex 2.12). One curve per τ, in its colour."));
    m_tauList->setAccessibleName(tr("Tensions τ"));
    m_tauList->setToolTip(tr("The tensions drawn, each with its colour and Processing's curveTightness(s), "
                             "τ = (1 − s)/2. Select one for the slider, the blending plot and the tangent table."));
    m_tauEdit->setPlaceholderText(tr("τ, e.g. 1/2 or -0.5"));
    m_tauEdit->setToolTip(tr("Type a tension as a decimal or a fraction (-1/2), between −10 and 10, and press Enter."));
    m_addTau->setText(tr("&Add"));
    m_addTau->setToolTip(tr("Add the typed tension: one more curve on the canvas (Ex 2.11 compares 0, 1/2 and 2)."));
    m_removeTau->setText(tr("&Remove"));
    m_removeTau->setToolTip(tr("Remove the selected tension and its curve."));
    m_tauSlider->setToolTip(tr("Drag to change the selected tension in steps of 0.05, from −10 to 10; the curve, "
                               "the blending functions and the exact panel follow."));
    m_curveBox->setTitle(tr("Curve (Def 2.10)"));
    m_endsLabel->setText(tr("&Ends:"));
    m_endsCombo->setItemText(0, tr("open (ends repeated)"));
    m_endsCombo->setItemText(1, tr("cyclic (n segments)"));
    m_endsCombo->setItemText(2, tr("closed (n + 1 segments)"));
    m_endsCombo->setItemText(3, tr("single segment (Def 2.8)"));
    m_endsCombo->setToolTip(tr("How the end segments get their missing neighbours (Def 2.10, Matlab Rep_CatmullRom): "
                               "open repeats q0 and qn (p1′(0) = τ(q1 − q0)); cyclic takes q₋₁ = qn and qn₊₁ = q0 "
                               "(n segments, Ex 2.13); closed adds the segment from qn back to q0; a single segment "
                               "(Def 2.8, Ex 2.11) keeps only the segments with both neighbours."));
    m_spacingLabel->setText(tr("&Parametrization:"));
    m_spacingCombo->setItemText(0, tr("uniform (thesis)"));
    m_spacingCombo->setItemText(1, tr("centripetal (α = 1/2)"));
    m_spacingCombo->setItemText(2, tr("chordal (α = 1)"));
    m_spacingCombo->setToolTip(tr("Knot spacing |qᵢ₊₁ − qᵢ|ᵅ. The thesis uses uniform spacing (α = 0). Beyond "
                                  "it: centripetal (α = 1/2) avoids cusps and loops, chordal (α = 1) follows the "
                                  "chord lengths; the segments then join with parallel tangents (G¹)."));
    m_bezierCheck->setText(tr("Compare with &Bézier"));
    m_bezierCheck->setToolTip(tr("Draw the Bézier curve that has the same points as control polygon (De Casteljau, "
                                 "Def 2.4): it passes only through q0 and qn, while Catmull-Rom passes through every "
                                 "point (§2.3)."));
    m_splineCheck->setText(tr("Cubic &spline (C²)"));
    m_splineCheck->setToolTip(tr("Draw the C² cubic spline of Def 2.3 through the same points, with the ends chosen below "
                                 "(a function of x: the abscissae must increase), and check its continuity at the knots: "
                                 "Bézier C^∞, Catmull-Rom C¹, cubic spline C² (§2.3, Ex 2.1)."));
    m_catmullRomCheck->setText(tr("Cat&mull-Rom curves"));
    m_catmullRomCheck->setToolTip(tr("Draw the Catmull-Rom curve of each tension. Hide them to see the cubic spline alone, "
                                     "as Fig 2.1 shows Ex 2.1's."));
    m_pointsCheck->setText(tr("Poin&ts"));
    m_pointsCheck->setToolTip(tr("Draw the points qᵢ that the curves interpolate, their labels and their polygon; off, "
                                 "the curves alone, like puntvis = false in the thesis's Matlab Rep_CatmullRom. The "
                                 "table still edits the points."));
    m_splineEndsLabel->setText(tr("Spline e&nds:"));
    m_splineEndsCombo->setItemText(0, tr("Natural (s″ = 0)"));
    m_splineEndsCombo->setItemText(1, tr("Clamped (slopes)"));
    m_splineEndsCombo->setItemText(2, tr("Not-a-knot"));
    m_splineEndsCombo->setItemText(3, tr("As Ex 2.1"));
    m_splineEndsCombo->setToolTip(tr("Def 2.3 leaves two degrees of freedom; the ends fix them. Natural: s″ = 0 at both "
                                     "ends. Clamped: the end slopes are given. Not-a-knot: the first two pieces are one "
                                     "cubic, and so are the last two. As Ex 2.1: the first piece is a parabola (s₁‴ = 0) "
                                     "and the last has no x² term — the ends that give Ex 2.1's pieces."));
    m_slopesLabel->setText(tr("End s&lopes:"));
    m_startSlopeEdit->setToolTip(tr("s′(x₀), the slope at the first point (clamped ends)"));
    m_endSlopeEdit->setToolTip(tr("s′(xₖ), the slope at the last point (clamped ends)"));
    m_compareCheck->setText(tr("Compare open and &cyclic ends"));
    m_compareCheck->setToolTip(tr("Also draw (dashed) and list the curve with the other end mode, as Ex 2.13 compares "
                                  "the cyclic and the open curve through the same points."));
    m_curvatureCheck->setText(tr("C&urvature κ(s) in the plot"));
    m_curvatureCheck->setToolTip(tr("Plot the signed curvature κ of every curve on the canvas against its arc length s "
                                    "instead of the blending functions: κ jumps at the knots of a Catmull-Rom curve "
                                    "(C¹, not C²) and is continuous along the C² cubic spline (§2.3)."));
    m_allTausCheck->setText(tr("Every &τ"));
    m_allTausCheck->setToolTip(tr("Plot the blending functions of every tension in the list (one line style per τ), "
                                  "as Ex 2.12 does for τ = −2, 0, 1/2 and 2."));
    m_exact->setToolTip(tr("Exact results: segment polynomials (Lemma 2.3, Def 2.10), tangents at the knots "
                           "(Prop 2.3), blending functions (Cor 2.1), and the comparisons of §2.3."));
    m_canvas->setToolTip(tr("Drag a point to move it; double-click to add one; Delete removes the selected point; "
                            "drag the paper to pan, wheel to zoom."));
    m_sideTabs->setAccessibleName(tr("Exact results and points"));
    m_sideTabs->setTabText(0, tr("Exact results"));
    m_sideTabs->setTabText(1, tr("Points"));
    m_sideTabs->setTabToolTip(0, m_exact->toolTip());
    m_sideTabs->setTabToolTip(1, tr("The points q0…qn as numbers; fractions such as 1/3 are accepted."));
    m_table->retranslate();
    syncControls();
    recompute();
}

QString CatmullRomTab::tensionItemText(const Rational& tau) const
{
    return tr("τ = %1   (curveTightness %2)").arg(tensionText(tau), tightnessString(tau));
}

void CatmullRomTab::syncControls()
{
    m_syncing = true;
    m_familyPanel->showSettings(m_settings, m_editor->selected());
    m_tensionBox->setVisible(m_settings.family == CurveFamily::CatmullRom); // the τ list is Catmull-Rom's
    const int count = static_cast<int>(m_settings.taus.size());
    if (m_tauList->count() != count) {
        m_tauList->clear();
        for (int i = 0; i < count; ++i)
            m_tauList->addItem(QString());
    }
    for (int i = 0; i < count; ++i) {
        QListWidgetItem* item = m_tauList->item(i);
        item->setText(tensionItemText(m_settings.taus[static_cast<std::size_t>(i)]));
        QPixmap swatch(14, 14);
        swatch.fill(tensionColour(m_settings.taus[static_cast<std::size_t>(i)]));
        item->setIcon(QIcon(swatch));
    }
    m_tauList->setCurrentRow(m_settings.selectedTau);
    const bool hasSelection = m_settings.selectedTau >= 0 && m_settings.selectedTau < count;
    m_removeTau->setEnabled(hasSelection && count > 1);
    m_tauSlider->setEnabled(hasSelection);
    if (hasSelection) {
        const Rational& tau = m_settings.taus[static_cast<std::size_t>(m_settings.selectedTau)];
        m_tauSlider->setValue(static_cast<int>(std::lround(toDouble(tau) * kSliderSteps)));
        m_sliderLabel->setText(
            tr("Selected: τ = %1, Processing's curveTightness(%2)").arg(tensionText(tau), tightnessString(tau)));
    }
    m_endsCombo->setCurrentIndex(static_cast<int>(m_settings.ends));
    m_spacingCombo->setCurrentIndex(static_cast<int>(m_settings.spacing));
    m_bezierCheck->setChecked(m_settings.bezier);
    m_splineCheck->setChecked(m_settings.spline);
    m_catmullRomCheck->setChecked(m_settings.catmullRom);
    m_catmullRomCheck->setEnabled(m_settings.family == CurveFamily::CatmullRom); // other families draw their own curve
    m_pointsCheck->setChecked(m_settings.controlPoints);
    m_splineEndsCombo->setCurrentIndex(static_cast<int>(m_settings.splineEnds));
    m_splineEndsCombo->setEnabled(m_settings.spline);
    m_splineEndsLabel->setEnabled(m_settings.spline);
    const bool clamped = m_settings.spline && m_settings.splineEnds == SplineEnds::Clamped;
    m_startSlopeEdit->setText(tensionText(m_settings.startSlope));
    m_endSlopeEdit->setText(tensionText(m_settings.endSlope));
    for (QWidget* w : std::initializer_list<QWidget*>{m_slopesLabel, m_startSlopeEdit, m_endSlopeEdit})
        w->setVisible(clamped);
    m_compareCheck->setChecked(m_settings.compareEnds);
    m_allTausCheck->setChecked(m_settings.allTausInPlot);
    m_allTausCheck->setEnabled(!m_settings.curvaturePlot); // the blending functions only
    m_curvatureCheck->setChecked(m_settings.curvaturePlot);
    setCatmullRomPlotTexts(m_plotTitle, m_plot, m_settings.curvaturePlot);
    // The same height whatever the number of τ (it scrolls past kTauListRows), and room for two
    // lines of the slider's label whatever τ it names: adding a τ never moves the check boxes
    // below under the pointer.
    m_tauList->setFixedHeight(kTauListRows * (m_tauList->fontMetrics().height() + 6) + 6);
    m_sliderLabel->setMinimumHeight(2 * m_sliderLabel->fontMetrics().lineSpacing());
    m_syncing = false;
}

// ---------------------------------------------------------------- edits

void CatmullRomTab::refuse(const QString& message)
{
    m_lastMessage = message;
    emit statusMessage(message);
}

void CatmullRomTab::changeSettings(const CatmullRomSettings& after, const QString& undoText, bool mergeable, int familyMergeId)
{
    if (after == m_settings)
        return;
    // Slider moves merge while they drag the same τ of the same list (the family's sliders: their own id).
    const int mergeId = familyMergeId >= 0 ? familyMergeId
                        : mergeable ? kSliderMergeIdBase + (after.selectedTau + 1) * 32 + static_cast<int>(after.taus.size())
                                    : -1;
    m_undo->push(new ValueCommand<CatmullRomSettings>([this](const CatmullRomSettings& s) { applySettings(s); }, m_settings,
                                                      after, undoText, mergeId));
}

void CatmullRomTab::applySettings(const CatmullRomSettings& s)
{
    m_settings = s;
    m_editor->setHandlesVisible(s.controlPoints);
    syncControls();
    recompute();
    emit documentChanged();
}

bool CatmullRomTab::addTension(const QString& text)
{
    TensionProblem problem = TensionProblem::None;
    const auto tau = parseTension(typedToC(text), &problem);
    if (!tau) {
        if (problem == TensionProblem::OutOfRange)
            refuse(tr("τ = %1 is outside [−10, 10]: beyond that the curve is all overshoot. Not added.").arg(text.trimmed()));
        else
            refuse(tr("“%1” is not a tension: type a decimal (0.5) or a fraction (-1/2). Not added.").arg(text.trimmed()));
        return false;
    }
    if (std::find(m_settings.taus.begin(), m_settings.taus.end(), *tau) != m_settings.taus.end()) {
        refuse(tr("τ = %1 is already in the list.").arg(tensionText(*tau)));
        return false;
    }
    if (static_cast<int>(m_settings.taus.size()) >= CatmullRomSettings::kMaxTensions) {
        refuse(tr("At most %n tensions at a time: remove one first.", nullptr, CatmullRomSettings::kMaxTensions));
        return false;
    }
    CatmullRomSettings after = m_settings;
    after.taus.push_back(*tau);
    after.selectedTau = static_cast<int>(after.taus.size()) - 1;
    changeSettings(after, tr("Add τ = %1").arg(tensionText(*tau)));
    refuse(tr("Added τ = %1.").arg(tensionText(*tau)));
    return true;
}

bool CatmullRomTab::removeTension(int index)
{
    if (index < 0 || index >= static_cast<int>(m_settings.taus.size()))
        return false;
    if (m_settings.taus.size() <= 1) {
        refuse(tr("At least one tension is needed."));
        return false;
    }
    CatmullRomSettings after = m_settings;
    const Rational removed = after.taus[static_cast<std::size_t>(index)];
    after.taus.erase(after.taus.begin() + index);
    after.selectedTau = std::min(index, static_cast<int>(after.taus.size()) - 1);
    changeSettings(after, tr("Remove τ = %1").arg(tensionText(removed)));
    return true;
}

void CatmullRomTab::setSelectedTension(int index)
{
    if (index < 0 || index >= static_cast<int>(m_settings.taus.size()) || index == m_settings.selectedTau)
        return;
    // The document keeps which τ is selected (the slider edits it): one undo step.
    CatmullRomSettings after = m_settings;
    after.selectedTau = index;
    changeSettings(after, tr("Select τ = %1").arg(tensionText(after.taus[static_cast<std::size_t>(index)])));
}

void CatmullRomTab::sliderMoved(int value)
{
    const int index = m_settings.selectedTau;
    if (index < 0 || index >= static_cast<int>(m_settings.taus.size()))
        return;
    const Rational tau = frac(value, kSliderSteps);
    for (std::size_t i = 0; i < m_settings.taus.size(); ++i)
        if (static_cast<int>(i) != index && m_settings.taus[i] == tau) {
            refuse(tr("τ = %1 is already in the list.").arg(tensionText(tau)));
            syncControls(); // the slider back on the selected τ
            return;
        }
    CatmullRomSettings after = m_settings;
    after.taus[static_cast<std::size_t>(index)] = tau;
    changeSettings(after, tr("Change τ"), true);
}

void CatmullRomTab::setEnds(CatmullRomEnds ends)
{
    CatmullRomSettings after = m_settings;
    after.ends = ends;
    changeSettings(after, tr("Change the ends"));
    if (ends == CatmullRomEnds::Segment && m_editor->points().size() != 4)
        refuse(tr("A single segment uses four points p0…p3 and joins p1 to p2; with more points, every segment "
                  "that has both neighbours is drawn."));
}

void CatmullRomTab::setSpacing(CatmullRomSpacing spacing)
{
    CatmullRomSettings after = m_settings;
    after.spacing = spacing;
    changeSettings(after, tr("Change the parametrization"));
}

void CatmullRomTab::setControlPointsVisible(bool on)
{
    CatmullRomSettings after = m_settings;
    after.controlPoints = on;
    changeSettings(after, on ? tr("Show the points") : tr("Hide the points"));
}

void CatmullRomTab::setBezierVisible(bool on)
{
    CatmullRomSettings after = m_settings;
    after.bezier = on;
    changeSettings(after, on ? tr("Show the Bézier curve") : tr("Hide the Bézier curve"));
}

void CatmullRomTab::setSplineVisible(bool on)
{
    CatmullRomSettings after = m_settings;
    after.spline = on;
    changeSettings(after, on ? tr("Show the cubic spline") : tr("Hide the cubic spline"));
}

void CatmullRomTab::setSplineEnds(SplineEnds ends)
{
    CatmullRomSettings after = m_settings;
    after.splineEnds = ends;
    changeSettings(after, tr("Change the spline's ends"));
}

void CatmullRomTab::setSplineSlopes(const Rational& start, const Rational& end)
{
    CatmullRomSettings after = m_settings;
    after.startSlope = start;
    after.endSlope = end;
    changeSettings(after, tr("Change the spline's end slopes"));
}

void CatmullRomTab::setCatmullRomVisible(bool on)
{
    CatmullRomSettings after = m_settings;
    after.catmullRom = on;
    changeSettings(after, on ? tr("Show the Catmull-Rom curves") : tr("Hide the Catmull-Rom curves"));
}

void CatmullRomTab::setCompareEnds(bool on)
{
    CatmullRomSettings after = m_settings;
    after.compareEnds = on;
    changeSettings(after, tr("Compare the ends"));
}

void CatmullRomTab::setAllTausInPlot(bool on)
{
    CatmullRomSettings after = m_settings;
    after.allTausInPlot = on;
    changeSettings(after, tr("Blending functions of every τ"));
}

void CatmullRomTab::setCurvaturePlot(bool on)
{
    CatmullRomSettings after = m_settings;
    after.curvaturePlot = on;
    changeSettings(after, on ? tr("Plot the curvature") : tr("Plot the blending functions"));
}

void CatmullRomTab::pointsEdited()
{
    recompute();
    updateContentBounds(false);
    emit documentChanged();
}

// ---------------------------------------------------------------- computing and showing

void CatmullRomTab::recompute()
{
    m_scene = computeScene(m_editor->points(), m_settings);
    updateFamilyViews();
    m_splinePanels->showState(m_settings, m_scene, m_editor->points());
    // The panel describes the curve drawn: the family's own when it is not Catmull-Rom.
    m_exact->setContent(m_settings.family != CurveFamily::CatmullRom
                            ? FamilyReport::html(m_editor->points(), m_editor->allExactPoints(), m_settings, m_scene)
                            : CatmullRomReport::html(m_editor->points(), m_settings, m_scene,
                                                     computeAnalysis(m_editor->allExactPoints(), m_settings)));
    updatePlot();
    m_canvas->update();
    updateCanvasSummary();
    for (const CatmullRomCurve& c : m_scene.curves)
        if (!c.error.isEmpty()) {
            refuse(c.error);
            break;
        }
    if (m_settings.spline && !m_scene.splineError.isEmpty())
        refuse(m_scene.splineError);
}

void CatmullRomTab::updateCanvasSummary()
{
    QStringList taus;
    for (const Rational& tau : m_settings.taus)
        taus << displayText(toString(tau));
    m_canvas->setAccessibleName(tr("Catmull-Rom canvas"));
    m_canvas->setAccessibleDescription(
        tr("Catmull-Rom curves through %n point(s), tensions τ = %1.", nullptr, static_cast<int>(m_editor->points().size()))
            .arg(taus.isEmpty() ? tr("none") : taus.join(QStringLiteral("; "))));
}

void CatmullRomTab::updatePlot() { updateCatmullRomPlot(m_plot, font(), m_settings, m_scene, presentationScale(presentation())); }

QRectF CatmullRomTab::contentBounds() const { return catmullRomContentBounds(m_editor->points(), m_settings, m_scene); }

void CatmullRomTab::updateContentBounds(bool force)
{
    if (!force) {
        const auto& points = m_editor->points();
        // Edits keep the view unless a point leaves it (never during a drag: the handle must
        // stay under the mouse).
        if (QGuiApplication::mouseButtons() != Qt::NoButton)
            return;
        const QRectF visible = m_canvas->view().visibleModelRect();
        bool outside = false;
        for (const Point& p : points)
            outside = outside || !visible.contains(QPointF(p.x, p.y));
        if (!outside)
            return;
    }
    m_canvas->setContentBounds(contentBounds());
}

void CatmullRomTab::drawLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style) const
{
    drawCanvasLegend(p, view, style, legend(), legendBox(view, style));
}

QRectF CatmullRomTab::legendRect(const ViewTransform& view, const CanvasStyle& style) const { return legendBox(view, style).box; }

CanvasLegendBox CatmullRomTab::legendBox(const ViewTransform& view, const CanvasStyle& style) const
{
    // As the De Casteljau tab's key: where it covers least of the curves drawn, and clear of
    // the points and their labels (Fig 2.10's key covered q0's label in the top-left corner).
    CanvasLegendObstacles avoid = catmullRomLegendObstacles(view, m_settings, m_scene);
    for (const PointEditor::Mark& mark : m_editor->marks(view, style))
        avoid.keepClear.push_back(mark.label.isEmpty() ? mark.handle : mark.handle.united(mark.label));
    return canvasLegendRect(view, style, legend(), avoid);
}

CanvasLegend CatmullRomTab::legend() const { return catmullRomLegend(m_settings, m_scene); }

// ---------------------------------------------------------------- view

void CatmullRomTab::presentationChanged(bool)
{
    syncControls();
    updatePlot();
}

void CatmullRomTab::changeEvent(QEvent* event)
{
    CurveTab::changeEvent(event);
    // Presentation mode changes the application font: the plot's legend and axes follow.
    if (event->type() == QEvent::FontChange && m_plot)
        updatePlot();
}

} // namespace granota::ui
