#include "ui/frog/frog_tab.h"

#include "core/softbody/scenes/scene.h"
#include "ui/common/tab_order.h"
#include "ui/common/value_command.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_parameters_panel.h"
#include "ui/frog/frog_plot_panel.h"
#include "ui/common/number_text.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFrame>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include "ui/common/vertical_scroll_area.h"

#include <QScrollArea>
#include <QShortcut>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

/// \file frog_tab_controls.cpp
/// FrogTab, part: the side panel and the stage built (scene, solver, knobs, Bézier outline,
/// parameters, overlays; the canvas with its warning and timeline), and their signals wired.

namespace granota::ui {

void FrogTab::buildControls()
{
    auto* side = new QWidget(this);
    auto* column = new QVBoxLayout(side);

    // Scene, solver, pause / step / reset.
    m_sceneBox = new QGroupBox(side);
    auto* sceneGrid = new QGridLayout(m_sceneBox);
    m_sceneLabel = new QLabel(m_sceneBox);
    m_sceneCombo = new QComboBox(m_sceneBox);
    m_sceneCombo->setObjectName(QStringLiteral("frogScene"));
    m_sceneCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_sceneCombo->setMinimumContentsLength(14);
    m_sceneCombo->setMaxVisibleItems(18);
    for (const std::string& name : sceneNames())
        m_sceneCombo->addItem(QString(), QString::fromStdString(name));
    m_description = new QLabel(m_sceneBox);
    m_description->setWordWrap(true);
    m_description->setTextFormat(Qt::PlainText);
    m_solverLabel = new QLabel(m_sceneBox);
    m_solverCombo = new QComboBox(m_sceneBox);
    m_solverCombo->setObjectName(QStringLiteral("frogSolver"));
    m_solverCombo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_solverCombo->setMinimumContentsLength(10);
    m_solverCombo->addItem(QString(), QStringLiteral("seed"));
    m_solverCombo->addItem(QString(), QStringLiteral("stable"));
    m_pause = new QPushButton(m_sceneBox);
    m_pause->setObjectName(QStringLiteral("frogPause"));
    m_pause->setCheckable(true);
    m_step = new QPushButton(m_sceneBox);
    m_step->setObjectName(QStringLiteral("frogStep"));
    m_reset = new QPushButton(m_sceneBox);
    m_reset->setObjectName(QStringLiteral("frogReset"));
    for (QPushButton* b : {m_pause, m_step, m_reset})
        b->setFocusPolicy(Qt::TabFocus); // Tab reaches them; a click leaves the space bar with the canvas (Annex II's spawn)
    m_solverNote = new QLabel(m_sceneBox);
    m_solverNote->setObjectName(QStringLiteral("frogSolverNote"));
    m_solverNote->setWordWrap(true);
    m_solverNote->setStyleSheet(QStringLiteral("color: #a4431b;"));
    m_solverNote->hide();
    m_speedLabel = new QLabel(m_sceneBox);
    m_speedCombo = new QComboBox(m_sceneBox);
    m_speedCombo->setObjectName(QStringLiteral("frogSpeed"));
    for (double speed : StepPacer::kSpeeds)
        m_speedCombo->addItem(FrogRun::speedLabel(speed) + QStringLiteral("×"), speed);
    m_speedCombo->setCurrentIndex(m_speedCombo->findData(1.0));
    m_speedLabel->setBuddy(m_speedCombo);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_pause);
    buttons->addWidget(m_step);
    buttons->addWidget(m_reset);
    sceneGrid->addWidget(m_sceneLabel, 0, 0);
    sceneGrid->addWidget(m_sceneCombo, 0, 1);
    sceneGrid->addWidget(m_description, 1, 0, 1, 2);
    sceneGrid->addWidget(m_solverLabel, 2, 0);
    sceneGrid->addWidget(m_solverCombo, 2, 1);
    sceneGrid->addWidget(m_solverNote, 3, 0, 1, 2);
    sceneGrid->addLayout(buttons, 4, 0, 1, 2);
    sceneGrid->addWidget(m_speedLabel, 5, 0);
    sceneGrid->addWidget(m_speedCombo, 5, 1);
    m_showPlots = new QCheckBox(m_sceneBox);
    m_showPlots->setObjectName(QStringLiteral("frogShowPlots"));
    sceneGrid->addWidget(m_showPlots, 6, 0, 1, 2);
    sceneGrid->setColumnStretch(1, 1);
    column->addWidget(m_sceneBox);

    // The stable solver's knobs, shown while it runs.
    m_stableBox = new QGroupBox(side);
    m_stableBox->setObjectName(QStringLiteral("frogStableBox"));
    auto* stableGrid = new QGridLayout(m_stableBox);
    m_substepsLabel = new QLabel(m_stableBox);
    m_substeps = new QSpinBox(m_stableBox);
    m_substeps->setObjectName(QStringLiteral("frogSubsteps"));
    m_substeps->setRange(StableSettings::kMinSubsteps, StableSettings::kMaxSubsteps);
    m_substeps->setKeyboardTracking(false);
    m_substepsLabel->setBuddy(m_substeps);
    m_complianceLabel = new QLabel(m_stableBox);
    m_compliance = new QDoubleSpinBox(m_stableBox);
    m_compliance->setObjectName(QStringLiteral("frogEdgeCompliance"));
    m_compliance->setRange(0, StableSettings::kMaxEdgeCompliance);
    m_compliance->setDecimals(4);
    m_compliance->setSingleStep(0.0005);
    m_compliance->setKeyboardTracking(false);
    m_complianceLabel->setBuddy(m_compliance);
    // The same stiffness as the frequency an edge rings at (Box2D's soft constraints).
    m_hertzLabel = new QLabel(m_stableBox);
    m_hertz = new QDoubleSpinBox(m_stableBox);
    m_hertz->setObjectName(QStringLiteral("frogEdgeHertz"));
    m_hertz->setDecimals(2);
    m_hertz->setSingleStep(1);
    m_hertz->setKeyboardTracking(false);
    m_hertzLabel->setBuddy(m_hertz);
    m_dampingLabel = new QLabel(m_stableBox);
    m_damping = new QDoubleSpinBox(m_stableBox);
    m_damping->setObjectName(QStringLiteral("frogEdgeDamping"));
    m_damping->setRange(0, StableSettings::kMaxEdgeDampingRatio);
    m_damping->setDecimals(2);
    m_damping->setSingleStep(0.05);
    m_damping->setKeyboardTracking(false);
    m_dampingLabel->setBuddy(m_damping);
    m_stableNote = new QLabel(m_stableBox);
    m_stableNote->setObjectName(QStringLiteral("frogStableNote"));
    m_stableNote->setWordWrap(true);
    m_softBodyReport = new QPushButton(m_stableBox);
    m_softBodyReport->setObjectName(QStringLiteral("frogSoftBodyReport"));
    stableGrid->addWidget(m_substepsLabel, 0, 0);
    stableGrid->addWidget(m_substeps, 0, 1);
    stableGrid->addWidget(m_complianceLabel, 1, 0);
    stableGrid->addWidget(m_compliance, 1, 1);
    stableGrid->addWidget(m_hertzLabel, 2, 0);
    stableGrid->addWidget(m_hertz, 2, 1);
    stableGrid->addWidget(m_dampingLabel, 3, 0);
    stableGrid->addWidget(m_damping, 3, 1);
    stableGrid->addWidget(m_stableNote, 4, 0, 1, 2);
    stableGrid->addWidget(m_softBodyReport, 5, 0, 1, 2);
    stableGrid->setColumnStretch(1, 1);
    column->addWidget(m_stableBox);

    // §4.9/4.10: precomputed points or the per-frame fit.
    m_bezierBox = new QGroupBox(side);
    auto* bezierLayout = new QVBoxLayout(m_bezierBox);
    m_precomputed = new QRadioButton(m_bezierBox);
    m_precomputed->setObjectName(QStringLiteral("frogBezierPrecomputed"));
    m_fit = new QRadioButton(m_bezierBox);
    m_fit->setObjectName(QStringLiteral("frogBezierFit"));
    m_precomputed->setChecked(true);
    auto* bezierGroup = new QButtonGroup(m_bezierBox);
    bezierGroup->addButton(m_precomputed);
    bezierGroup->addButton(m_fit);
    m_fitCost = new QLabel(m_bezierBox);
    m_fitCost->setWordWrap(true);
    bezierLayout->addWidget(m_precomputed);
    bezierLayout->addWidget(m_fit);
    bezierLayout->addWidget(m_fitCost);
    column->addWidget(m_bezierBox);

    m_paramBox = new QGroupBox(side);
    auto* paramLayout = new QVBoxLayout(m_paramBox);
    paramLayout->addWidget(m_params);
    column->addWidget(m_paramBox);

    m_overlayBox = new QGroupBox(side);
    auto* overlayGrid = new QGridLayout(m_overlayBox);
    // One check box per row of the overlays' table (frog_overlays.h), in its order.
    for (std::size_t i = 0; i < m_overlayBoxes.size(); ++i) {
        QCheckBox* box = new QCheckBox(m_overlayBox);
        m_overlayBoxes[i] = box;
        box->setObjectName(QStringLiteral("frogOverlay%1").arg(i));
        overlayGrid->addWidget(box, int(i / 2), int(i % 2));
        connect(box, &QCheckBox::toggled, this, &FrogTab::overlaysChanged);
    }
    column->addWidget(m_overlayBox);

    m_hint = new QLabel(side);
    m_hint->setWordWrap(true);
    m_note = new QLabel(side);
    m_note->setObjectName(QStringLiteral("frogNote"));
    m_note->setWordWrap(true);
    m_note->setStyleSheet(QStringLiteral("color: #a4431b;"));
    m_note->hide();
    // A refusal that goes away leaves its room: the panel keeps its height, and its scroll
    // bar stays where the user had it (at the bottom, it would have jumped).
    QSizePolicy notePolicy = m_note->sizePolicy();
    notePolicy.setRetainSizeWhenHidden(true);
    m_note->setSizePolicy(notePolicy);
    column->addWidget(m_hint);
    column->addWidget(m_note);
    column->addStretch(1);

    auto* scroll = new VerticalScrollArea(side, this); // Tab goes to its controls, and it scrolls to the one focused
    m_scroll = scroll;
    m_side = side;
    side->installEventFilter(this); // its layout changes with the scene: keep it unclipped

    // The canvas with its timeline, and under them the plots over time when they are shown.
    auto* stage = new QWidget(this);
    auto* stageLayout = new QVBoxLayout(stage);
    stageLayout->setContentsMargins(0, 0, 0, 0);
    stageLayout->setSpacing(2);
    stageLayout->addWidget(m_canvas, 1);
    // A warning a teacher can act on: the seed has blown up, with the two ways out.
    m_explosion = new QFrame(stage);
    m_explosion->setObjectName(QStringLiteral("frogExplosion"));
    m_explosion->setStyleSheet(
        QStringLiteral("#frogExplosion { background: #fdecea; border: 1px solid #d9826f; border-radius: 3px; }"));
    auto* explosionRow = new QHBoxLayout(m_explosion);
    explosionRow->setContentsMargins(6, 3, 6, 3);
    m_explosionText = new QLabel(m_explosion);
    m_explosionText->setWordWrap(true);
    m_explosionText->setStyleSheet(QStringLiteral("color: #7a2412;"));
    m_explosionReset = new QPushButton(m_explosion);
    m_explosionReset->setObjectName(QStringLiteral("frogExplosionReset"));
    m_explosionStable = new QPushButton(m_explosion);
    m_explosionStable->setObjectName(QStringLiteral("frogExplosionStable"));
    explosionRow->addWidget(m_explosionText, 1);
    explosionRow->addWidget(m_explosionReset);
    explosionRow->addWidget(m_explosionStable);
    m_explosion->hide();
    stageLayout->addWidget(m_explosion);
    auto* timelineRow = new QHBoxLayout;
    timelineRow->setContentsMargins(6, 0, 6, 2);
    m_timeline = new QSlider(Qt::Horizontal, stage);
    m_timeline->setObjectName(QStringLiteral("frogTimeline"));
    m_timeline->setRange(0, 0);
    m_timeline->setSingleStep(1);
    m_timeline->setPageStep(kStepsPerSecond);
    m_timelineLabel = new QLabel(stage);
    m_timelineLabel->setObjectName(QStringLiteral("frogTimelineLabel"));
    m_timelineLabel->setBuddy(m_timeline);
    m_markButton = new QPushButton(stage);
    m_markButton->setObjectName(QStringLiteral("frogStopwatch"));
    m_markButton->setCheckable(true);
    m_markButton->setFocusPolicy(Qt::TabFocus);
    timelineRow->addWidget(m_timeline, 1);
    timelineRow->addWidget(m_timelineLabel);
    timelineRow->addWidget(m_markButton);
    stageLayout->addLayout(timelineRow);
    m_plots = new FrogPlotPanel(this);
    m_plots->hide();
    auto* left = new QSplitter(Qt::Vertical, this);
    left->addWidget(stage);
    left->addWidget(m_plots);
    left->setStretchFactor(0, 1);
    left->setStretchFactor(1, 0);
    left->setCollapsible(0, false);
    left->setCollapsible(1, false);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(left);
    splitter->addWidget(scroll);
    setSidePanel(scroll);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 0);
    splitter->setCollapsible(0, false);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);
    // Tab reaches the canvas first, then its timeline, then the side panel.
    setTabOrderOf({m_canvas, m_explosionReset, m_explosionStable, m_timeline, m_markButton, m_plots, side});
}

void FrogTab::connectControls()
{
    connect(m_sceneCombo, &QComboBox::activated, this, &FrogTab::sceneChosen);
    connect(m_solverCombo, &QComboBox::activated, this, &FrogTab::solverChosen);
    connect(m_pause, &QPushButton::toggled, this, &FrogTab::setPaused);
    connect(m_step, &QPushButton::clicked, this, &FrogTab::stepOnce);
    connect(m_showPlots, &QCheckBox::toggled, this, &FrogTab::setPlotsShown);
    connect(m_plots, &FrogPlotPanel::statusMessage, this, &TabPage::statusMessage);
    connect(m_plots, &FrogPlotPanel::bodyChosen, m_canvas, &FrogCanvas::setMarkedBody);
    connect(m_speedCombo, &QComboBox::activated, this, [this](int index) { setSpeed(m_speedCombo->itemData(index).toDouble()); });
    connect(m_reset, &QPushButton::clicked, this, &FrogTab::reset);
    connect(m_fit, &QRadioButton::toggled, this, [this](bool fit) {
        auto apply = [this](bool on) {
            const QSignalBlocker b1(m_fit), b2(m_precomputed);
            (on ? m_fit : m_precomputed)->setChecked(true);
            m_canvas->setBezierOutline(on ? FrogCanvas::BezierOutline::Fit : FrogCanvas::BezierOutline::Precomputed);
            retranslate();
            emit documentChanged();
        };
        m_undo->push(new ValueCommand<bool>(apply, !fit, fit, (fit ? m_fit : m_precomputed)->text()));
    });
    connect(m_canvas, &FrogCanvas::fitCostChanged, this, [this](double us) {
        if (m_fit->isChecked())
            m_fitCost->setText(tr("Cost of the fit: %1 µs per frame.").arg(displayFixed(us, 1)));
    });
    connect(m_canvas, &FrogCanvas::statusMessage, this, &TabPage::statusMessage);
    connect(m_run, &FrogRun::statusMessage, this, &TabPage::statusMessage);
    connect(m_run, &FrogRun::timelineChanged, this, &FrogTab::updateTimeline);
    connect(m_run, &FrogRun::blownUpChanged, this, &FrogTab::showExplosion);
    const auto knob = [this](StableKnob k, double value) {
        const std::string_view name = stableKnobName(k);
        const QString key = QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
        QString error;
        if (!editStableSetting(key, value, &error)) {
            showStableSettings(); // the knob shows the value in force again
            showRefusal(error);
        }
    };
    connect(m_substeps, &QSpinBox::valueChanged, this, [knob](int n) { knob(StableKnob::Substeps, n); });
    connect(m_compliance, &QDoubleSpinBox::valueChanged, this, [knob](double a) { knob(StableKnob::EdgeCompliance, a); });
    connect(m_hertz, &QDoubleSpinBox::valueChanged, this, [this, knob](double hertz) {
        // A frequency is a compliance for this scene's edge (edgeComplianceForHertz).
        const auto spring = edgeSpringShown();
        if (spring && hertz > 0)
            knob(StableKnob::EdgeCompliance,
                 std::clamp(edgeComplianceForHertz(hertz, spring->restLength, spring->vertexMass, kStepsPerSecond), 0.0,
                            StableSettings::kMaxEdgeCompliance));
    });
    connect(m_damping, &QDoubleSpinBox::valueChanged, this, [knob](double z) { knob(StableKnob::EdgeDampingRatio, z); });
    connect(m_softBodyReport, &QPushButton::clicked, this, [this] { emit reportRequested(QStringLiteral("soft-body")); });
    connect(m_explosionReset, &QPushButton::clicked, this, &FrogTab::reset);
    connect(m_explosionStable, &QPushButton::clicked, this, [this] {
        const int stable = m_solverCombo->findData(QStringLiteral("stable"));
        solverChosen(stable); // as the solver box does it: one undo step
    });
    connect(m_timeline, &QSlider::valueChanged, this, &FrogTab::timelineMoved);
    connect(m_markButton, &QPushButton::clicked, this, &FrogTab::toggleMark);
    connect(m_canvas, &FrogCanvas::mouseRadiusChanged, this, [this](double) {
        // §4.1: the mouse sets the radius; the field shows it (no undo step, nothing rebuilt).
        // The run holds it (FrogRun::sceneAsEdited): the panel shows it.
        if (scene().hasParam("radius"))
            m_params->setValues(m_run->sceneAsEdited());
    });
    connect(m_params, &FrogParametersPanel::edited, this, [this](const QString& key, int part, int index, double value) {
        QString error;
        if (!editParameterNumber(key, part, index, value, &error)) {
            m_params->setValues(m_run->sceneAsEdited()); // the field shows the value in force again
            showRefusal(error);
        }
    });

    // Single keys, whenever the tab is shown (a hidden widget's shortcut never fires), even
    // before anything in it was clicked; a text field being typed in keeps its letters (it
    // takes them first, as ShortcutOverride). The space bar is the canvas's spawn key.
    const auto shortcut = [this](QKeySequence keys, auto slot) {
        auto* s = new QShortcut(keys, this);
        s->setContext(Qt::WindowShortcut);
        connect(s, &QShortcut::activated, this, slot);
    };
    shortcut(QKeySequence(Qt::Key_P), [this] { m_pause->toggle(); });
    shortcut(QKeySequence(Qt::Key_S), [this] { stepOnce(); });
    shortcut(QKeySequence(Qt::Key_Period), [this] { stepOnce(); });
    shortcut(QKeySequence(Qt::Key_Comma), [this] { stepBack(); });
    shortcut(QKeySequence(Qt::Key_M), [this] { toggleMark(); });
    shortcut(QKeySequence(Qt::Key_R), [this] { reset(); });
    // Slower and faster: the speed box's neighbours.
    const auto nudgeSpeed = [this](int by) {
        const int i = std::clamp(m_speedCombo->currentIndex() + by, 0, m_speedCombo->count() - 1);
        setSpeed(m_speedCombo->itemData(i).toDouble());
    };
    shortcut(QKeySequence(Qt::Key_BracketLeft), [nudgeSpeed] { nudgeSpeed(-1); });
    shortcut(QKeySequence(Qt::Key_BracketRight), [nudgeSpeed] { nudgeSpeed(1); });
}

} // namespace granota::ui
