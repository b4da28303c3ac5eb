#include "ui/frog/frog_tab.h"
#include "ui/common/error_text.h"
#include "ui/common/number_text.h"
#include "ui/common/path_recorder.h"

#include "core/softbody/outline.h"
#include "core/softbody/scenes/scene_texts.h"
#include "core/base/math_constants.h"
#include "core/base/number_format.h"
#include "ui/common/value_command.h"
#include "ui/common/tab_order.h"
#include "ui/common/widest_text_width.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_json.h"
#include "ui/frog/frog_parameters_panel.h"
#include "ui/frog/frog_plot_panel.h"
#include "ui/shell/exporter.h"
#include "ui/shell/tikz_writer.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFrame>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QImage>
#include <QJsonArray>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QSpinBox>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QSplitter>
#include <QTextStream>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

namespace {

void setError(QString* error, const QString& text)
{
    if (error)
        *error = text;
}

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

constexpr int kParameterMergeIdBase = 0x46520000; ///< "FR": a parameter's edits merge (valueMergeId)
constexpr int kStableMergeIdBase = 0x46530000;    ///< "FS": a stable solver knob's edits merge

QJsonValue paramValue(const SceneSpec& scene, const QString& key)
{
    const Json doc = sceneToJson(scene);
    const Json* v = doc.find("params")->find(key.toStdString());
    return v ? toQJson(*v) : QJsonValue();
}

/// Flips Processing's y (down) for TikZ (up).
std::vector<Point> flipped(const std::vector<Point>& points, double height)
{
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Point& p : points)
        out.emplace_back(p.x, height - p.y);
    return out;
}

} // namespace

const long FrogTab::kLoadSeekWork = 600 * FrogCanvas::kFrameWork;
const std::size_t FrogTab::kKeptRunBytes = FrogRun::kSnapshotBytes;

struct FrogTab::KeptRun {
    std::unique_ptr<FrogRun::KeptRun> canvas;
    SceneSpec scene;
    SolverKind solver = SolverKind::Seed;
    long mark = -1;
};

FrogTab::FrogTab(QWidget* parent)
    : TabPage(QStringLiteral("frog"), QT_TR_NOOP("Frog"), parent), m_run(new FrogRun), m_canvas(new FrogCanvas(m_run, this)),
      m_params(new FrogParametersPanel(this))
{
    m_run->setParent(this); // after the canvas: the run outlives its view
    setExportView(m_canvas);
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
        m_sceneCombo->addItem(QString(), fromStd(name));
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
        m_speedCombo->addItem(FrogCanvas::speedLabel(speed) + QStringLiteral("×"), speed);
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
    m_showVertices = new QCheckBox(m_overlayBox);
    m_showSprings = new QCheckBox(m_overlayBox);
    m_showArea = new QCheckBox(m_overlayBox);
    m_showVelocities = new QCheckBox(m_overlayBox);
    m_showReadouts = new QCheckBox(m_overlayBox);
    m_showFrameTime = new QCheckBox(m_overlayBox);
    m_showGhost = new QCheckBox(m_overlayBox);
    m_showTrail = new QCheckBox(m_overlayBox);
    m_showPairs = new QCheckBox(m_overlayBox);
    m_showProtractor = new QCheckBox(m_overlayBox);
    const OverlayBoxes boxes = overlayBoxes();
    int i = 0;
    for (QCheckBox* box : boxes) {
        box->setObjectName(QStringLiteral("frogOverlay%1").arg(i));
        overlayGrid->addWidget(box, i / 2, i % 2);
        connect(box, &QCheckBox::toggled, this, &FrogTab::overlaysChanged);
        ++i;
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

    auto* scroll = new QScrollArea(this);
    scroll->setFocusPolicy(Qt::NoFocus); // Tab goes to its controls, and it scrolls to the one focused
    scroll->setWidget(side);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
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
    connect(m_canvas, &FrogCanvas::mouseRadiusChanged, this, [this](double radius) {
        // §4.1: the mouse sets the radius; the field shows it (no undo step, nothing rebuilt).
        if (!m_scene.hasParam("radius") || m_scene.params.radius == radius)
            return;
        m_scene.params.radius = radius;
        m_params->setValues(m_scene);
    });
    connect(m_params, &FrogParametersPanel::edited, this, [this](const QString& key, const QJsonValue& value) {
        QString error;
        if (!editParameter(key, value, &error)) {
            m_params->setValues(m_scene); // the field shows the value in force again
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

    QString error;
    auto frog = loadScene("frog");
    if (frog)
        rebuild(*frog, SolverKind::Seed, &error);
    showScene();
}

// ---------------------------------------------------------------- scene and solver

bool FrogTab::rebuild(const SceneSpec& scene, SolverKind solver, QString* error)
{
    auto sim = Simulation::create(scene, solver);
    if (!sim) {
        setError(error, tr("The simulation cannot be built with these values: %1").arg(ErrorText::of(sim.error())));
        return false;
    }
    auto replaced = std::make_unique<KeptRun>();
    replaced->scene = m_scene;
    replaced->solver = m_solver;
    replaced->mark = m_mark;
    m_scene = scene;
    m_solver = solver;
    m_mark = -1; // a new run: the stopwatch's mark was of the old one
    replaced->canvas = m_canvas->replaceRun(std::move(sim).value());
    m_replaced.reset();
    if (replaced->canvas) {
        m_replaced = std::make_shared<RunSlot>();
        m_replaced->run = std::move(replaced);
    }
    if (m_plots)
        m_plots->refresh(true); // a new run: a new series
    updateTimeline();
    return true;
}

std::shared_ptr<FrogTab::RunSlot> FrogTab::takeReplaced()
{
    std::shared_ptr<RunSlot> slot = std::move(m_replaced);
    m_replaced.reset();
    if (!slot)
        slot = std::make_shared<RunSlot>();
    keepWithinBudget(slot);
    return slot;
}

void FrogTab::keepWithinBudget(const std::shared_ptr<RunSlot>& slot)
{
    // Newest last; the expired (steps gone from the history) and `slot`'s old place go.
    m_keptSlots.erase(std::remove_if(m_keptSlots.begin(), m_keptSlots.end(),
                                     [&slot](const std::weak_ptr<RunSlot>& w) {
                                         const auto s = w.lock();
                                         return !s || s == slot;
                                     }),
                      m_keptSlots.end());
    m_keptSlots.push_back(slot);
    std::size_t total = 0;
    for (const auto& w : m_keptSlots)
        if (const auto s = w.lock(); s && s->run)
            total += s->run->canvas->bytes();
    for (const auto& w : m_keptSlots) {
        if (total <= kKeptRunBytes)
            break;
        const auto s = w.lock();
        if (s && s->run && s != slot) {
            total -= s->run->canvas->bytes();
            s->run.reset();
            s->released = true;
        }
    }
}

void FrogTab::swapRun(RunSlot& slot)
{
    std::unique_ptr<KeptRun> shown;
    if (m_replaced) // the run shown before the undo step applied its state
        shown = std::move(m_replaced->run);
    m_replaced.reset();
    if (slot.run) {
        m_scene = slot.run->scene;
        m_solver = slot.run->solver;
        m_canvas->restoreRun(std::move(slot.run->canvas)); // the run just built is let go
        m_mark = slot.run->mark;
        if (m_plots)
            m_plots->refresh(true);
        updateTimeline();
    } else if (slot.released) {
        emit statusMessage(tr("The run from before this step was not kept (too much memory): the scene starts again."));
    }
    slot.run = std::move(shown);
    slot.released = false;
    const auto kept = std::find_if(m_keptSlots.begin(), m_keptSlots.end(),
                                   [&slot](const std::weak_ptr<RunSlot>& w) { return w.lock().get() == &slot; });
    if (kept != m_keptSlots.end())
        keepWithinBudget(kept->lock()); // the newest kept now
}

void FrogTab::sayRunReplaced(const RunSlot& slot)
{
    if (!slot.run)
        return;
    const long steps = slot.run->canvas->run->recordedSteps();
    if (steps > 0)
        emit statusMessage(tr("The scene starts again; Undo brings back the run of %n step(s) it replaced.", nullptr,
                              int(std::min<long>(steps, std::numeric_limits<int>::max()))));
}

QString FrogTab::sceneLoadError(const QString& name, const Error& coreError)
{
    QStringList names;
    for (const std::string& n : sceneNames())
        names << fromStd(n);
    // A known scene that fails to load is a fault in its file (or in how it is read):
    // the core's own message says which, and hiding it behind "unknown" hides the cause.
    // A fault of the installation's own file is named in the core's words, as a report would
    // quote them; a refusal the core names a sentence for is said in the interface's language.
    if (names.contains(name))
        return tr("The scene “%1” cannot be loaded: %2")
            .arg(name, coreError.id == MessageId::None ? fromStd(coreError.message) : ErrorText::of(coreError));
    return tr("Unknown scene “%1”. The scenes are: %2.").arg(name, names.join(QStringLiteral(", ")));
}

bool FrogTab::setScene(const QString& name, QString* error)
{
    if (!switchScene(name, error))
        return false;
    m_undo->clear(); // a scene set from outside (a document, the command line) starts a history
    m_replaced.reset();
    return true;
}

bool FrogTab::switchScene(const QString& name, QString* error)
{
    auto spec = loadScene(name.toStdString());
    if (!spec) {
        setError(error, sceneLoadError(name, spec.error()));
        return false;
    }
    // The seed never had collisions (§5.2 is future work): those scenes start on the stable
    // solver, as in granota-cli; the solver box switches back to compare.
    spec->stable = knobsInForce(); // the solver's knobs stay with the solver
    SolverKind solver = m_solver;
    const bool collisions = spec->has(SceneComponent::Collisions) || spec->has(SceneComponent::Obstacles);
    if (collisions)
        solver = SolverKind::Stable;
    if (!rebuild(*spec, solver, error))
        return false;
    m_note->hide();
    showScene();
    emit documentChanged();
    return true;
}

StableSettings FrogTab::knobsInForce() const
{
    const Simulation* sim = m_canvas->simulation();
    return sim ? sim->stableSettings() : m_scene.stable;
}

SceneSpec FrogTab::sceneWithKnobsInForce() const
{
    SceneSpec spec = m_scene;
    spec.stable = knobsInForce();
    return spec;
}

bool FrogTab::setSolver(SolverKind solver, QString* error)
{
    if (!rebuild(sceneWithKnobsInForce(), solver, error))
        return false;
    m_note->hide();
    showScene();
    emit documentChanged();
    return true;
}

QJsonObject FrogTab::sceneState() const
{
    const QJsonObject state = saveState();
    QJsonObject scene;
    for (const char* key : {"scene", "solver", "params", "stable"})
        scene.insert(QLatin1String(key), state.value(QLatin1String(key)));
    return scene;
}

void FrogTab::pushSceneStep(const QJsonObject& before, const QString& undoText)
{
    const QJsonObject after = sceneState();
    if (after == before)
        return;
    const std::shared_ptr<RunSlot> kept = takeReplaced(); // the run before the change, for Undo
    auto apply = [this, kept](const QJsonObject& state) {
        QString error;
        if (applyState(state, &error)) // states this tab wrote itself: cannot be refused
            swapRun(*kept);
        else
            showRefusal(error);
        emit documentChanged();
    };
    m_undo->push(new ValueCommand<QJsonObject>(apply, before, after, undoText, -1, {false, /*appliedAlready=*/true}));
    sayRunReplaced(*kept);
}

void FrogTab::sceneChosen(int index)
{
    const QJsonObject before = sceneState();
    QString error;
    if (!switchScene(m_sceneCombo->itemData(index).toString(), &error)) {
        showScene();
        showRefusal(error);
        return;
    }
    pushSceneStep(before, tr("Stage: %1").arg(m_sceneCombo->itemText(index)));
}

void FrogTab::solverChosen(int index)
{
    const QJsonObject before = sceneState();
    QString error;
    if (!setSolver(index == 1 ? SolverKind::Stable : SolverKind::Seed, &error)) {
        showScene();
        showRefusal(error);
        return;
    }
    pushSceneStep(before, tr("Solver: %1").arg(m_solverCombo->itemText(index)));
}

void FrogTab::reset()
{
    QString error;
    if (!rebuild(sceneWithKnobsInForce(), m_solver, &error)) // a new run with the knobs as they are
        showRefusal(error);
    else
        emit statusMessage(tr("The scene starts again."));
    m_replaced.reset(); // Reset lets the run go
}

void FrogTab::showScene()
{
    const QString name = fromStd(m_scene.name);
    const QSignalBlocker b1(m_sceneCombo), b2(m_solverCombo);
    m_sceneCombo->setCurrentIndex(std::max(0, m_sceneCombo->findData(name)));
    m_solverCombo->setCurrentIndex(m_solver == SolverKind::Stable ? 1 : 0);
    m_params->setScene(m_scene);
    m_bezierBox->setVisible(m_scene.has(SceneComponent::OutlineBezier));
    retranslate();
    fitSidePanel();
}

void FrogTab::fitSidePanel()
{
    // Wide enough for the parameters' rows (they change with the scene and the font), so
    // that nothing is clipped; the canvas takes the rest.
    if (!m_scroll)
        return;
    const int comfortable = m_side->fontMetrics().averageCharWidth() * 50;
    const int needed = m_side->minimumSizeHint().width() + m_scroll->verticalScrollBar()->sizeHint().width() + 4;
    m_scroll->setMinimumWidth(std::max(comfortable, needed));
}

bool FrogTab::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_side && event->type() == QEvent::LayoutRequest)
        QMetaObject::invokeMethod(this, &FrogTab::fitSidePanel, Qt::QueuedConnection);
    return TabPage::eventFilter(watched, event);
}

void FrogTab::changeEvent(QEvent* event)
{
    TabPage::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        fitSidePanel();
}

void FrogTab::showRefusal(const QString& message)
{
    m_note->setText(message);
    m_note->show();
    emit statusMessage(message);
}

// ---------------------------------------------------------------- parameters

bool FrogTab::applyParameter(const QString& key, const QJsonValue& value, QString* error)
{
    if (!m_scene.hasParam(key.toStdString())) {
        setError(error, tr("Scene “%1” has no parameter “%2”.").arg(fromStd(m_scene.name), key));
        return false;
    }
    // One member set and checked: the scene is not written to JSON and read back (issue 35).
    auto spec = withParameter(m_scene, key.toStdString(), fromQJson(value));
    if (!spec) {
        setError(error, tr("This value was refused: %1").arg(ErrorText::of(spec.error())));
        return false;
    }
    // The core has no setter on a running Simulation: the scene is built again with the new
    // value (the bodies start again; pause, overlays, solver and outline stay).
    if (!rebuild(*spec, m_solver, error))
        return false;
    m_params->setValues(m_scene);
    m_note->hide();
    emit documentChanged();
    return true;
}

bool FrogTab::editParameter(const QString& key, const QJsonValue& value, QString* error)
{
    const QJsonValue before = paramValue(m_scene, key);
    if (!applyParameter(key, value, error))
        return false;
    // The run the value replaced goes with the step: Undo brings it back as it was.
    const std::shared_ptr<RunSlot> kept = takeReplaced();
    auto apply = [this, key, kept](const QJsonValue& v) {
        if (applyParameter(key, v, nullptr))
            swapRun(*kept);
    };
    // Consecutive edits of the same parameter merge, so that spinning an arrow is one step:
    // the step keeps the run from before the first of them.
    const int index = m_undo->index();
    m_undo->push(new ValueCommand<QJsonValue>(apply, before, value,
                                              tr("Change %1").arg(ErrorText::parameterLabel(key.toStdString())),
                                              valueMergeId(kParameterMergeIdBase, key),
                                              {/*dropWhenUnchanged=*/false, /*appliedAlready=*/true}));
    const bool merged = m_undo->index() == index;
    if (!merged)
        m_lastParameterSlot = kept;
    if (const auto shown = merged ? m_lastParameterSlot.lock() : kept)
        sayRunReplaced(*shown);
    return true;
}

// ---------------------------------------------------------------- run controls

void FrogTab::setPaused(bool paused)
{
    m_canvas->setRunning(!paused);
    retranslate();
}

void FrogTab::stepOnce()
{
    if (!m_pause->isChecked())
        m_pause->setChecked(true); // a single step pauses first
    m_canvas->step();
}

FrogTab::OverlayBoxes FrogTab::overlayBoxes() const
{
    return {m_showVertices,  m_showSprings, m_showArea,  m_showVelocities, m_showReadouts,
            m_showFrameTime, m_showGhost,   m_showTrail, m_showPairs,      m_showProtractor};
}

FrogTab::OverlayFlags FrogTab::overlayFlags() const
{
    OverlayFlags flags{};
    const OverlayBoxes boxes = overlayBoxes();
    for (std::size_t i = 0; i < flags.size(); ++i)
        flags[i] = boxes[i]->isChecked();
    return flags;
}

void FrogTab::applyOverlayFlags(const OverlayFlags& flags)
{
    const OverlayBoxes boxes = overlayBoxes();
    for (std::size_t i = 0; i < flags.size(); ++i) {
        const QSignalBlocker block(boxes[i]);
        boxes[i]->setChecked(flags[i]);
    }
    FrogCanvas::Overlays o;
    o.vertices = m_showVertices->isChecked();
    o.springs = m_showSprings->isChecked();
    o.area = m_showArea->isChecked();
    o.velocities = m_showVelocities->isChecked();
    o.readouts = m_showReadouts->isChecked();
    o.frameTime = m_showFrameTime->isChecked();
    o.ghost = m_showGhost->isChecked();
    o.trail = m_showTrail->isChecked();
    o.pairs = m_showPairs->isChecked();
    o.protractor = m_showProtractor->isChecked();
    m_canvas->setOverlays(o);
    emit documentChanged();
}

void FrogTab::overlaysChanged()
{
    auto* box = qobject_cast<QCheckBox*>(sender());
    OverlayFlags before = overlayFlags();
    const OverlayBoxes boxes = overlayBoxes();
    for (std::size_t i = 0; i < before.size(); ++i)
        if (boxes[i] == box)
            before[i] = !before[i]; // the box has toggled already
    m_undo->push(new ValueCommand<OverlayFlags>([this](const OverlayFlags& f) { applyOverlayFlags(f); }, before, overlayFlags(),
                                                box ? box->text().remove(QLatin1Char('&')) : tr("Overlays")));
}

void FrogTab::setPresentation(bool on)
{
    m_canvas->setPresentation(on);
    m_plots->setPresentation(on);
}

// ---------------------------------------------------------------- texts

QString FrogTab::sceneTitle(const QString& name) const
{
    const SceneText* text = findSceneText(name.toStdString());
    return text ? QString::fromLatin1(text->section) + QLatin1Char(' ') +
                      QCoreApplication::translate(kSceneTextContext, text->title)
                : name;
}

QString FrogTab::sceneDescription(const QString& name) const
{
    const SceneText* text = findSceneText(name.toStdString());
    return text ? QCoreApplication::translate(kSceneTextContext, text->description) : QString();
}

QString FrogTab::sceneHint() const
{
    if (m_scene.model == SceneModel::Pendulum)
        return tr("The pendulum hangs from the mouse: move the mouse over the picture.");
    if (m_scene.model == SceneModel::Stage) {
        if (m_scene.components.empty())
            return tr("Move the mouse up and down: the radius is r = |mouseY − h/2| (§4.1).");
        if (m_scene.has(SceneComponent::Bounce))
            return tr("Click to start the polygon again at the mouse (§4.3).");
        return tr("Reset (R) drops the polygon again.");
    }
    return tr("Drag the body with the left button. Space drops a new one at the mouse and holds it until you let go "
              "(Annex II).");
}

QString FrogTab::hint() const
{
    return tr("Drag the body with the mouse; Space on the canvas spawns one at the mouse. P pauses, S steps, R resets.");
}

QString FrogTab::keyboardHint() const
{
    return tr("Keys: the arrows move the cursor, G grabs, L lays a ruler, Space spawns a body; P pauses, S steps, R "
              "resets.");
}

void FrogTab::retranslate()
{
    m_sceneBox->setTitle(tr("Scene"));
    m_sceneLabel->setText(tr("Stage"));
    for (int i = 0; i < m_sceneCombo->count(); ++i)
        m_sceneCombo->setItemText(i, sceneTitle(m_sceneCombo->itemData(i).toString()));
    m_sceneCombo->setToolTip(tr("The stages of chapter 4, in the thesis's order, and the future work of §5.2. "
                                "Each scene builds, draws and shows only its own components."));
    m_description->setText(sceneDescription(fromStd(m_scene.name)));
    m_solverLabel->setText(tr("Solver"));
    m_solverCombo->setItemText(0, tr("Seed (Annex II)"));
    m_solverCombo->setItemText(1, tr("Stable (XPBD)"));
    m_solverCombo->setToolTip(tr("Seed: the thesis's own schemes, reproduced faithfully (Annex II). Stable: beyond the "
                                 "thesis, position-based constraints with compliance (XPBD) that hold the target "
                                 "area and stay stable on stiff and extreme settings. Switching starts the scene again."));
    m_canvas->setAccessibleName(tr("Frog canvas"));
    m_canvas->setSceneSummary(
        tr("Scene %1, %2 solver")
            .arg(sceneTitle(fromStd(m_scene.name)), m_solverCombo->itemText(m_solver == SolverKind::Stable ? 1 : 0)));
    m_pause->setText(m_pause->isChecked() ? tr("Run") : tr("Pause"));
    keepWidestTextWidth(m_pause, {tr("Run"), tr("Pause")}); // one width, running or not
    m_pause->setToolTip(tr("Pause or run the animation, one fixed step per frame at 60 frames per second (P)."));
    m_step->setText(tr("Step"));
    m_step->setToolTip(tr("One fixed step, as one call of actualitza() in Annex II; pauses first (S or .)."));
    m_speedLabel->setText(tr("Speed"));
    m_showPlots->setText(tr("Plots over time"));
    m_showPlots->setToolTip(tr("Under the canvas: the energies, what damping and the rest took, the area error, the "
                               "largest stretch and the contacts as the run goes on; the pendulums' phase plot. "
                               "Pause freezes them; they export as CSV."));
    m_speedCombo->setToolTip(tr("Slow motion steps once every few frames and fast runs several steps a frame: the "
                                "step itself never changes, so the seed goes through exactly the states of Annex II "
                                "([ slower, ] faster)."));
    m_timeline->setToolTip(tr("The run so far, step by step: drag to go back to any step (the run pauses there). "
                              "Running on replays what was recorded until a press on a body, a spawn or a change "
                              "takes over (, one step back, . one step on)."));
    m_timeline->setAccessibleName(tr("Timeline"));
    m_stableBox->setTitle(tr("Stable solver"));
    m_substepsLabel->setText(tr("Substeps n"));
    m_substeps->setToolTip(tr("Substeps per step, 1 to 32: each step is cut into n substeps, and the constraints' error "
                              "falls like 1/n² at a cost proportional to n. The run goes on with it from the next step, and the "
                              "recording keeps the change."));
    m_complianceLabel->setText(tr("Edge compliance α"));
    m_compliance->setToolTip(tr("How soft the body's edges are, in step² per unit of mass and per px of rest length: "
                                "0 is rigid, larger is softer. Unlike the seed's factors it does not depend on the "
                                "substeps or the number of vertices. The run goes on with it from the next step, and the "
                                "recording keeps the change."));
    m_hertzLabel->setText(tr("Edge frequency f"));
    m_hertz->setSuffix(tr(" Hz"));
    m_hertz->setToolTip(tr("The same stiffness as a frequency, as Box2D states its soft constraints: how many times a "
                           "second an edge of this body rings on its own (α = 0, rigid, rings at none). Setting it sets "
                           "the compliance."));
    m_dampingLabel->setText(tr("Edge damping ratio ζ"));
    m_damping->setToolTip(tr("A dashpot along each edge, as a damping ratio: 0 none, 1 critical (an edge stretched and "
                             "let go comes back without ringing), above 1 slower still. What it takes shows in the "
                             "plots as damping. The run goes on with it from the next step, and the recording keeps "
                             "the change."));
    m_softBodyReport->setText(tr("Error against substeps…"));
    m_softBodyReport->setToolTip(tr("The soft-body report below the tab: XPBD's constraint error against the substeps "
                                    "and their cost (View ▸ Error against run time)."));
    showStableSettings();
    m_explosionText->setText(tr("The body has blown up."));
    m_explosionStable->setText(tr("Use the Stable solver"));
    m_explosionStable->setToolTip(tr("The same scene and values on the stable solver (XPBD), which holds them."));
    m_timelineDigits = -1; // the label's width, for this language's text
    m_markButton->setText(tr("Stopwatch"));
    m_markButton->setToolTip(tr("Marks the step shown; the label then counts the steps and seconds since it, as the "
                                "run goes on or the timeline moves (M). Again: clears the mark."));
    updateTimeline();
    m_reset->setText(tr("Reset"));
    m_reset->setToolTip(tr("Start the scene again with the current parameters (R)."));
    m_explosionReset->setText(m_reset->text()); // the same Reset, where the warning is
    m_explosionReset->setToolTip(m_reset->toolTip());
    m_solverNote->setText(tr("The seed solver has no angle constraints: these shapes round into blobs. The Stable "
                             "solver keeps their form."));
    m_solverNote->setVisible(m_solver == SolverKind::Seed && seedRoundsShapes(m_scene));

    m_bezierBox->setTitle(tr("Bézier outline (§4.9)"));
    m_precomputed->setText(tr("Precomputed points"));
    m_precomputed->setToolTip(tr("The thesis's choice (§4.9, §4.10): the polygon is the control polygon of a Bézier "
                                 "curve sampled once by De Casteljau (Def 2.4); the samples are the body's vertices."));
    m_fit->setText(tr("Least-squares fit every frame"));
    m_fit->setToolTip(tr("The option §4.9 abandoned as too costly for Processing: every frame, the least-squares "
                         "Bézier curve through the outline (Lemma 2.2, Prop 2.2). With M⁺ computed once, a frame "
                         "costs one small matrix product; the curve need not pass through the vertices (Note 2.3)."));
    if (!m_fit->isChecked())
        m_fitCost->setText(tr("Precomputed points: nothing to compute per frame."));
    else
        m_fitCost->setText(tr("Cost of the fit: %1 µs per frame.").arg(displayFixed(m_canvas->fitMicroseconds(), 1)));

    m_paramBox->setTitle(tr("Parameters"));
    m_paramBox->setToolTip(tr("Only this scene's parameters, with the names of Annex II. Changes apply at once: the "
                              "scene starts again with them."));
    m_params->retranslate();

    m_overlayBox->setTitle(tr("Overlays"));
    m_showVertices->setText(tr("Vertices"));
    m_showVertices->setToolTip(tr("The body's vertices, numbered as in Annex II's arrays (v₀ under the head), and the "
                                  "joints of the legs."));
    m_showSprings->setText(tr("Springs"));
    m_showSprings->setToolTip(tr("The polygon's edges: the springs of §4.4 that keep neighbours at their length."));
    m_showArea->setText(tr("Area vs target"));
    m_showArea->setToolTip(tr("The body's area by the trapezoid rule against the target area (§4.5); the bar's "
                              "mark is the target."));
    m_showVelocities->setText(tr("Velocities"));
    m_showVelocities->setToolTip(tr("Each vertex's move in the last step, x − x_prev (Verlet, Def 3.1), drawn four "
                                    "times longer."));
    m_showReadouts->setText(tr("Readouts"));
    m_showReadouts->setToolTip(tr("What the solver measures: area error, largest stretch of an edge, largest "
                                  "correction or constraint force, kinetic and potential energy."));
    m_showGhost->setText(tr("Ghost of the other solver"));
    m_showGhost->setToolTip(tr("Both solvers at once: the other solver runs the same scene, fed the same mouse, and "
                               "is drawn dashed over this one (the seed's frog sits about 17 % short of its area, "
                               "the stable one holds it)."));
    m_showPairs->setText(tr("Broad phase"));
    m_showPairs->setToolTip(tr("§5.2.2: the pairs of bodies whose boxes overlap, the only ones tested for contact "
                               "(a uniform grid finds them), and how many contacts there are (stable solver)."));
    m_showProtractor->setText(tr("Protractor"));
    m_showProtractor->setToolTip(tr("§4.15: each joint's angle, in degrees, over the range its limits allow (shaded); red "
                                    "when the joint is held at a limit."));
    m_showTrail->setText(tr("Trail"));
    m_showTrail->setToolTip(tr("The path of one point over the last 10 s: the pendulum's tip or the first body's vertex 0; "
                               "Shift+click on a vertex or a joint to follow it."));
    m_showFrameTime->setText(tr("Frame time"));
    m_showFrameTime->setToolTip(tr("Time per frame and per simulation step, in milliseconds, averaged a few times a "
                                   "second."));
    m_hint->setText(sceneHint());
}

void FrogTab::setPlotsShown(bool on)
{
    if (m_showPlots->isChecked() != on) {
        const QSignalBlocker block(m_showPlots);
        m_showPlots->setChecked(on);
    }
    m_canvas->setRecordingSeries(on);
    m_plots->setRun(m_run, &m_scene);
    m_plots->setVisible(on); // at the height it asks for (FrogPlotPanel::sizeHint), the canvas the rest
    m_canvas->setMarkedBody(on ? m_plots->body() : -1);
}

void FrogTab::updateTimeline()
{
    const long end = m_canvas->recordedSteps();
    const long now = m_canvas->simulation() ? m_canvas->simulation()->stepCount() : 0;
    const int top = int(std::min<long>(end, std::numeric_limits<int>::max()));
    if (m_timeline->maximum() != top || (!m_timeline->isSliderDown() && m_timeline->value() != now)) {
        const QSignalBlocker block(m_timeline);
        m_timeline->setMaximum(top);
        if (!m_timeline->isSliderDown())
            m_timeline->setValue(int(std::min<long>(now, top)));
    }
    // A knob turned at a step the run replays or goes back past: the boxes show it.
    if (m_stableBox && knobsInForce() != m_knobsShown)
        showStableSettings();
    if (m_mark > end) // the run was cut off before the mark
        m_mark = -1;
    if (m_markButton->isChecked() != (m_mark >= 0)) {
        const QSignalBlocker block(m_markButton);
        m_markButton->setChecked(m_mark >= 0);
    }
    const QString text = tr("Step %1 of %2 · %3 s");
    QString shown = text.arg(now).arg(end).arg(displayFixed(double(now) / kStepsPerSecond, 2));
    if (m_mark >= 0) {
        const long since = now - m_mark, steps = std::labs(since);
        const QString seconds = displayFixed(double(steps) / kStepsPerSecond, 2);
        shown += QLatin1Char('\n') + (since >= 0 ? tr("%1 s (%n steps) since step %2", "", int(steps))
                                                 : tr("%1 s (%n steps) before step %2", "", int(steps)))
                                         .arg(seconds)
                                         .arg(m_mark);
    }
    m_timelineLabel->setText(shown);
    // Room for the stopwatch's second line, marked or not: the canvas keeps its size when it appears.
    m_timelineLabel->setMinimumHeight(2 * m_timelineLabel->fontMetrics().lineSpacing());
    // As wide as the widest text with this many digits, so that the slider does not jitter.
    const int digits = int(QString::number(end).size());
    if (digits == m_timelineDigits)
        return;
    m_timelineDigits = digits;
    const QString eights = QString(digits, QLatin1Char('8'));
    const int wide = m_timelineLabel->fontMetrics().horizontalAdvance(
        text.arg(eights, eights)
            .arg(displayFixed(double(end) / kStepsPerSecond, 2)
                     .replace(QRegularExpression(QStringLiteral("\\d")), QStringLiteral("8"))));
    m_timelineLabel->setMinimumWidth(wide);
}

bool FrogTab::applyStableSettings(const StableSettings& settings, QString* error)
{
    // Live: the run goes on from where it is, and records the change at its step.
    if (!m_canvas->setStableSettings(settings)) {
        setError(error, tr("The stable solver's knobs were refused: substeps from %1 to %2, compliance from 0 to %3, "
                           "damping ratio from 0 to %4.")
                            .arg(StableSettings::kMinSubsteps)
                            .arg(StableSettings::kMaxSubsteps)
                            .arg(displayNumber(StableSettings::kMaxEdgeCompliance))
                            .arg(displayNumber(StableSettings::kMaxEdgeDampingRatio)));
        return false;
    }
    showStableSettings();
    emit documentChanged();
    return true;
}

bool FrogTab::editStableSetting(const QString& key, double value, QString* error)
{
    SceneSpec changed = sceneWithKnobsInForce();
    const auto ok = applySetting(changed, key.toStdString() + "=" + formatDouble(value));
    if (!ok) {
        setError(error, tr("This value was refused: %1").arg(ErrorText::of(ok.error())));
        return false;
    }
    const StableSettings before = knobsInForce(), after = changed.stable;
    if (after == before)
        return true;
    if (!applyStableSettings(after, error))
        return false;
    // The undo entry names the knob by its label on screen, not its key in the file.
    const QLabel* label = key == QLatin1String("substeps")          ? m_substepsLabel
                          : key == QLatin1String("edge_compliance") ? m_complianceLabel
                                                                    : m_dampingLabel;
    m_undo->push(new ValueCommand<StableSettings>([this](const StableSettings& s) { applyStableSettings(s, nullptr); }, before,
                                                  after, tr("Change %1").arg(label->text().remove(QLatin1Char('&'))),
                                                  valueMergeId(kStableMergeIdBase, key),
                                                  {/*dropWhenUnchanged=*/false, /*appliedAlready=*/true}));
    return true;
}

std::optional<Simulation::EdgeSpring> FrogTab::edgeSpringShown() const
{
    const Simulation* sim = m_canvas->simulation();
    return sim && sim->bodyCount() > 0 ? sim->edgeSpring(0) : std::nullopt;
}

void FrogTab::showStableSettings()
{
    const QSignalBlocker b1(m_substeps), b2(m_compliance), b3(m_hertz), b4(m_damping);
    const StableSettings knobs = knobsInForce();
    m_knobsShown = knobs;
    m_substeps->setValue(knobs.substeps);
    m_compliance->setValue(knobs.edgeCompliance);
    m_damping->setValue(knobs.edgeDampingRatio);
    m_stableBox->setVisible(m_solver == SolverKind::Stable);
    // What α means for this scene: the first edge of the first body, at rest, its vertex's mass.
    const auto spring = edgeSpringShown();
    // Rigid edges, or none: no frequency to state ("—").
    const double hertz = spring ? edgeRingHertz(knobs.edgeCompliance, spring->restLength, spring->vertexMass, kStepsPerSecond)
                                : 0.0;
    m_hertz->setEnabled(hertz > 0);
    m_hertz->setSpecialValueText(hertz > 0 ? QString() : QStringLiteral("—"));
    m_damping->setEnabled(spring.has_value());
    if (hertz > 0) {
        // The frequencies α from 0 to its largest gives, this edge's.
        const double softest = edgeRingHertz(StableSettings::kMaxEdgeCompliance, spring->restLength, spring->vertexMass,
                                             kStepsPerSecond);
        m_hertz->setRange(std::ceil(softest * 100) / 100, kMostEdgeHertz);
        m_hertz->setValue(hertz);
    } else {
        m_hertz->setRange(0, kMostEdgeHertz);
        m_hertz->setValue(0);
    }
    QString note;
    if (spring) {
        const double period = edgeRingPeriodSteps(knobs.edgeCompliance, spring->restLength, spring->vertexMass);
        if (std::isfinite(period))
            note = tr("An edge of %1 px rings with a period of %2 steps (%3 Hz at 60 steps a second); 0 makes the edges rigid.")
                       .arg(displayFixed(spring->restLength, 0), displayFixed(period, 1), displayFixed(hertz, 2));
        else
            note = tr("α = 0: the edges are rigid.");
    } else if (m_canvas->simulation()) {
        note = tr("This scene has no springs: the compliance and the damping ratio do nothing here.");
    }
    m_stableNote->setText(note);
}

void FrogTab::showExplosion(bool blownUp)
{
    m_explosion->setVisible(blownUp);
    m_explosionStable->setVisible(m_solver == SolverKind::Seed);
}

void FrogTab::timelineMoved(int step)
{
    // Scrubbing is looking: the run pauses there (P runs on, replaying what was recorded).
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    m_canvas->seek(step);
    m_plots->refresh(true);
}

void FrogTab::toggleMark()
{
    const Simulation* sim = m_canvas->simulation();
    m_mark = m_mark >= 0 || !sim ? -1 : sim->stepCount();
    if (m_mark >= 0)
        emit statusMessage(tr("Stopwatch: marked step %1; M again clears the mark.").arg(m_mark));
    updateTimeline();
}

void FrogTab::stepBack()
{
    const Simulation* sim = m_canvas->simulation();
    if (!sim)
        return;
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    if (sim->stepCount() == 0) {
        emit statusMessage(tr("Step 0: the run starts here."));
        return;
    }
    m_canvas->seek(sim->stepCount() - 1);
    m_plots->refresh(true);
}

void FrogTab::setSpeed(double speed)
{
    if (!m_canvas->setSpeed(speed))
        return;
    const QSignalBlocker block(m_speedCombo);
    m_speedCombo->setCurrentIndex(m_speedCombo->findData(speed));
}

// ---------------------------------------------------------------- document

QJsonObject FrogTab::saveState() const
{
    QJsonObject state;
    state.insert(QStringLiteral("scene"), fromStd(m_scene.name));
    state.insert(QStringLiteral("solver"), fromStd(solverName(m_solver)));
    state.insert(QStringLiteral("params"), toQJson(*sceneToJson(m_scene).find("params")));
    const FrogCanvas::Overlays& o = m_canvas->overlays();
    QJsonObject overlays;
    overlays.insert(QStringLiteral("vertices"), o.vertices);
    overlays.insert(QStringLiteral("springs"), o.springs);
    overlays.insert(QStringLiteral("area"), o.area);
    overlays.insert(QStringLiteral("velocities"), o.velocities);
    overlays.insert(QStringLiteral("readouts"), o.readouts);
    overlays.insert(QStringLiteral("frame_time"), o.frameTime);
    overlays.insert(QStringLiteral("ghost"), o.ghost);
    overlays.insert(QStringLiteral("trail"), o.trail);
    overlays.insert(QStringLiteral("pairs"), o.pairs);
    overlays.insert(QStringLiteral("protractor"), o.protractor);
    state.insert(QStringLiteral("overlays"), overlays);
    state.insert(QStringLiteral("bezier_outline"), m_fit->isChecked() ? QStringLiteral("fit") : QStringLiteral("precomputed"));
    state.insert(QStringLiteral("paused"), !m_canvas->running());
    state.insert(QStringLiteral("speed"), m_canvas->speed());
    if (const auto& ruler = m_canvas->ruler()) // a measure shown goes with the document, as the overlays do
        state.insert(QStringLiteral("ruler"), QJsonArray{ruler->first.x, ruler->first.y, ruler->second.x, ruler->second.y});
    // The knobs the run started with; the recording's events turn them on the way.
    state.insert(QStringLiteral("stable"), toQJson(stableSettingsToJson(m_scene.stable)));
    // The run so far (docs/rewind.md): its events, how far it went, and the step shown.
    if (const RecordedRun* run = m_canvas->run())
        state.insert(QStringLiteral("recording"), documentRunToQJson(*run));
    return state;
}

bool FrogTab::loadState(const QJsonObject& state, QString* error)
{
    if (state.isEmpty())
        return true; // a document without the frog's state: keep the tab as it is
    if (!applyState(state, error))
        return false;
    m_undo->clear();
    m_replaced.reset();
    return true;
}

bool FrogTab::applyState(const QJsonObject& state, QString* error)
{
    const QString name = state.value(QStringLiteral("scene")).toString();
    auto spec = loadScene(name.toStdString());
    if (!spec) {
        setError(error, sceneLoadError(name, spec.error()));
        return false;
    }
    SolverKind solver = SolverKind::Seed;
    if (state.contains(QStringLiteral("solver"))) {
        const QString s = state.value(QStringLiteral("solver")).toString();
        auto kind = parseSolverKind(s.toStdString());
        if (!kind) {
            setError(error, tr("Unknown solver “%1” (seed or stable).").arg(s));
            return false;
        }
        solver = *kind;
    }
    if (state.contains(QStringLiteral("params"))) {
        const QJsonValue params = state.value(QStringLiteral("params"));
        if (!params.isObject()) {
            setError(error, tr("The frog's parameters must be an object."));
            return false;
        }
        Json doc = sceneToJson(*spec);
        Json merged = *doc.find("params");
        const QJsonObject p = params.toObject();
        for (auto it = p.begin(); it != p.end(); ++it) {
            if (!spec->hasParam(it.key().toStdString())) {
                setError(error, tr("Scene “%1” has no parameter “%2”.").arg(name, it.key()));
                return false;
            }
            merged.set(it.key().toStdString(), fromQJson(it.value()));
        }
        doc.set("params", merged);
        auto parsed = parseScene(doc);
        if (!parsed) {
            setError(error, tr("This value was refused: %1").arg(ErrorText::of(parsed.error())));
            return false;
        }
        spec = std::move(parsed);
    }
    FrogCanvas::Overlays overlays = m_canvas->overlays();
    if (state.contains(QStringLiteral("overlays"))) {
        const QJsonValue v = state.value(QStringLiteral("overlays"));
        if (!v.isObject()) {
            setError(error, tr("The frog's overlays must be an object."));
            return false;
        }
        const QJsonObject o = v.toObject();
        const std::pair<const char*, bool*> flags[] = {{"vertices", &overlays.vertices}, {"springs", &overlays.springs},
                                                       {"area", &overlays.area},         {"velocities", &overlays.velocities},
                                                       {"readouts", &overlays.readouts}, {"frame_time", &overlays.frameTime},
                                                       {"ghost", &overlays.ghost},       {"trail", &overlays.trail},
                                                       {"pairs", &overlays.pairs},       {"protractor", &overlays.protractor}};
        for (const auto& [key, flag] : flags) {
            const QJsonValue f = o.value(QLatin1String(key));
            if (f.isUndefined())
                continue;
            if (!f.isBool()) {
                setError(error, tr("The overlay “%1” must be true or false.").arg(QLatin1String(key)));
                return false;
            }
            *flag = f.toBool();
        }
    }
    bool fit = m_fit->isChecked();
    if (state.contains(QStringLiteral("bezier_outline"))) {
        const QString b = state.value(QStringLiteral("bezier_outline")).toString();
        if (b != QLatin1String("fit") && b != QLatin1String("precomputed")) {
            setError(error, tr("The Bézier outline must be “precomputed” or “fit”, not “%1”.").arg(b));
            return false;
        }
        fit = b == QLatin1String("fit");
    }
    bool paused = m_pause->isChecked();
    if (state.contains(QStringLiteral("paused"))) {
        if (!state.value(QStringLiteral("paused")).isBool()) {
            setError(error, tr("“paused” must be true or false."));
            return false;
        }
        paused = state.value(QStringLiteral("paused")).toBool();
    }
    double speed = m_canvas->speed();
    if (state.contains(QStringLiteral("speed"))) {
        const QJsonValue v = state.value(QStringLiteral("speed"));
        const auto& speeds = StepPacer::kSpeeds;
        if (!v.isDouble() || std::find(speeds.begin(), speeds.end(), v.toDouble()) == speeds.end()) {
            setError(error, tr("The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4."));
            return false;
        }
        speed = v.toDouble();
    }
    // The stable solver's knobs, checked as a scene file's "stable".
    if (state.contains(QStringLiteral("stable"))) {
        Json doc = sceneToJson(*spec);
        doc.set("stable", fromQJson(state.value(QStringLiteral("stable"))));
        auto parsed = parseScene(doc);
        if (!parsed) {
            setError(error, tr("This value was refused: %1").arg(ErrorText::of(parsed.error())));
            return false;
        }
        spec = std::move(parsed);
    } else {
        spec->stable = m_scene.stable;
    }
    // The ruler's ends, scene px: four finite numbers.
    std::optional<std::pair<Point, Point>> ruler;
    if (state.contains(QStringLiteral("ruler"))) {
        const QJsonArray r = state.value(QStringLiteral("ruler")).toArray();
        const bool ok = r.size() == 4 && std::all_of(r.begin(), r.end(), [](const QJsonValue& v) {
                            return v.isDouble() && std::isfinite(v.toDouble()) && std::abs(v.toDouble()) <= 1e7;
                        });
        if (!ok) {
            setError(error, tr("The ruler must be four numbers: x and y of each end, in px."));
            return false;
        }
        ruler = std::pair{Point(r[0].toDouble(), r[1].toDouble()), Point(r[2].toDouble(), r[3].toDouble())};
    }
    // The recorded run: checked whole before anything changes.
    std::optional<DocumentRun> recorded;
    if (state.contains(QStringLiteral("recording"))) {
        auto parsed = documentRunFromQJson(state.value(QStringLiteral("recording")));
        if (!parsed) {
            setError(error, tr("The frog's recording was refused: %1").arg(ErrorText::of(parsed.error())));
            return false;
        }
        recorded = std::move(parsed).value();
    }
    if (!rebuild(*spec, solver, error))
        return false;
    if (recorded) {
        QString refused;
        if (!m_canvas->setRecording(std::move(recorded->events), recorded->steps, &refused))
            showRefusal(refused); // checked above: cannot happen
        const long work = m_canvas->simulation()->workPerStep() * recorded->step;
        if (work <= kLoadSeekWork)
            m_canvas->seek(recorded->step);
        else
            emit statusMessage(
                tr("The run was saved at step %1: drag the timeline to go there (it is long to replay).").arg(recorded->step));
    }
    setSpeed(speed);
    m_canvas->setRuler(ruler);
    // Everything is valid: show it.
    {
        const OverlayBoxes boxes = overlayBoxes();
        const OverlayFlags values = {overlays.vertices, overlays.springs,   overlays.area,  overlays.velocities,
                                     overlays.readouts, overlays.frameTime, overlays.ghost, overlays.trail,
                                     overlays.pairs,    overlays.protractor};
        for (std::size_t i = 0; i < values.size(); ++i) {
            const QSignalBlocker block(boxes[i]);
            boxes[i]->setChecked(values[i]);
        }
        m_canvas->setOverlays(overlays);
        const QSignalBlocker b1(m_fit), b2(m_precomputed);
        (fit ? m_fit : m_precomputed)->setChecked(true);
        m_canvas->setBezierOutline(fit ? FrogCanvas::BezierOutline::Fit : FrogCanvas::BezierOutline::Precomputed);
        const QSignalBlocker b3(m_pause);
        m_pause->setChecked(paused);
        m_canvas->setRunning(!paused);
    }
    m_note->hide();
    showScene();
    return true;
}

QString FrogTab::csv() const
{
    QString out;
    QTextStream s(&out);
    const Simulation* sim = m_canvas->simulation();
    s << "# scene " << fromStd(m_scene.name) << " (" << fromStd(m_scene.section) << "), solver " << fromStd(solverName(m_solver))
      << ", step " << (sim ? sim->stepCount() : 0) << "\n";
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
    const Simulation* sim = m_canvas->simulation();
    if (!sim)
        return;
    const double H = m_scene.params.height;
    w.comment(QStringLiteral("Granota: scene %1 (%2), solver %3, step %4")
                  .arg(fromStd(m_scene.name), fromStd(m_scene.section), fromStd(solverName(m_solver)))
                  .arg(sim->stepCount()));
    // The frame, so that the picture keeps the scene's proportions; what is drawn is clipped
    // to it, as the canvas clips to the scene (a foot past the floor is not drawn).
    const double W = m_scene.params.width;
    w.polyline({{0, 0}, {W, 0}, {W, H}, {0, H}}, QColor(0x9a, 0x9a, 0x9a), 0.4, false, true);
    w.clipTo({0, 0}, {W, H});
    // As FrogCanvas::drawScene paints them: filled stones and bodies, legs with their feet.
    const FrogArt& art = m_canvas->art();
    for (const ObstacleSpec& o : sim->obstacles()) {
        if (o.closed)
            w.polygon(flipped(o.points, H), art.stonePen().color(), FrogArt::stoneColour(), 0.8);
        else
            w.polyline(flipped(o.points, H), art.logPen().color(), 3.0);
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
        w.polygon(flipped(legOutline(pts[0], pts[1], pts[2], FrogCanvas::kLegHalfWidth, 6), H), art.legPen().color(),
                  FrogArt::skinColour(0), 0.6);
    };
    const bool frog = m_scene.model == SceneModel::Frog && sim->chainCount() >= 4;
    if (frog) {
        leg(2);
        leg(3);
    }
    const bool filled = m_scene.has(SceneComponent::Fill);
    for (int i = 0; i < sim->bodyCount(); ++i) {
        const std::vector<Point> outline = flipped(m_canvas->bodyOutline(i), H);
        if (filled)
            w.polygon(outline, art.bodyPen().color(), FrogArt::skinColour(i), 0.8);
        else
            w.polyline(outline, art.inkPen().color(), 0.7, false, true);
    }
    if (frog) {
        leg(0);
        leg(1);
    }
    if (m_scene.model == SceneModel::Frog && m_scene.has(SceneComponent::Head) && sim->bodyCount() > 0)
        drawTikzHead(w);
    if (m_scene.model == SceneModel::Pendulum)
        for (int c = 0; c < sim->chainCount(); ++c) {
            sim->chainJoints(c, pts);
            w.polyline(flipped(pts, H), QColor(0x37, 0x47, 0x4f), 1.5);
            for (const Point& p : pts)
                w.point(Point(p.x, H - p.y), QColor(0xf2, 0xb1, 0x34));
        }
}

void FrogTab::drawTikzHead(TikzWriter& w) const
{
    // The head as the canvas paints it over the body (FrogCanvas::drawScene), recorded as
    // paths (as Figs 4.11 and 4.12 are): each filled outline filled, each line drawn.
    const double H = m_scene.params.height;
    PathRecorder recorder(QSize(int(std::ceil(m_scene.params.width)), int(std::ceil(H))));
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
    const Simulation* sim = m_canvas->simulation();
    return sim ? sim->stepCount() : 0;
}

QString FrogTab::exportFrames(const QString& directory, int frames, QSize size, long firstStep)
{
    if (frames < 1)
        return tr("The number of frames must be at least 1.");
    if (directory.isEmpty() || (!QDir(directory).exists() && !QDir().mkpath(directory)))
        return tr("Cannot create the folder “%1”.").arg(directory);
    if (!m_canvas->simulation())
        return tr("There is no scene to export.");
    const QDir dir(directory);
    size = QSize(size.width() / 2 * 2, size.height() / 2 * 2); // even sides: yuv420p video
    if (size.width() < 16 || size.height() < 16)
        size = kFrameSize;
    // The run pauses (its timer would step it between frames) and goes back to the step the
    // user saw; the recorded run replays from there exactly.
    if (!m_pause->isChecked())
        m_pause->setChecked(true);
    if (firstStep >= 0 && firstStep != shownStep() && !m_canvas->seek(firstStep))
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
            m_canvas->step(); // the canvas's fixed step: one per frame, 60 per second
    }
    return {};
}

} // namespace granota::ui
