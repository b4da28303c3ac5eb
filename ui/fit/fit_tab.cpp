#include "ui/fit/fit_tab.h"
#include "ui/common/error_text.h"
#include "ui/fit/background_fit.h"
#include "core/base/number_format.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/number_text.h"

#include "core/curves/fitting/fit_warning.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/fit_error_by_degree.h"
#include "core/base/input_limits.h"
#include "core/io/point_list.h"
#include "core/io/worked_examples.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/drawable.h"
#include "ui/common/exact_panel.h"
#include "ui/fit/fit_error_plot.h"
#include "ui/fit/fit_exact_view.h"
#include "ui/common/point_editor.h"
#include "ui/common/point_extent.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/point_table.h"
#include "ui/common/plot_title_room.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/vertical_scroll_area.h"
#include "ui/common/value_command.h"
#include "ui/shell/file_dialogs.h"
#include "ui/shell/tikz_writer.h"
#include "ui/shell/user_file.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QUndoStack>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>

namespace granota::ui {

namespace {

constexpr int kMaxDegree = kMaxFitDegree; ///< the core's limit
constexpr int kMaxIterations = 1000;
/// Undo-merge fields of the settings' ValueCommand (changes of the same field merge).
enum Field { DegreeField, ParametrizationField, SolverField, CorrectionField };
constexpr int kFieldMergeIdBase = 0x46490000; ///< "FI": the merge id of field f is this + f
constexpr int kSamplesMergeId = 0x46540002;   ///< "FT": the samples spin box held down is one step

/// The degree spin box: refuses n > k with a reason instead of silently (docs/tabs.md).
class DegreeSpinBox : public QSpinBox {
public:
    using QSpinBox::QSpinBox;
    std::function<void(int)> refused; ///< called with the degree that was asked for

    /// Up stays enabled at the maximum (arrow, key, wheel), so that asking for more is
    /// answered with the reason rather than a greyed-out arrow that does nothing.
    StepEnabled stepEnabled() const override
    {
        StepEnabled e = QSpinBox::stepEnabled();
        if (isEnabled() && !isReadOnly() && refused)
            e |= StepUpEnabled;
        return e;
    }

    void stepBy(int steps) override
    {
        if (steps > 0 && value() + steps > maximum() && refused)
            refused(value() + steps);
        QSpinBox::stepBy(steps);
    }

protected:
    QValidator::State validate(QString& input, int& pos) const override
    {
        bool ok = false;
        const int v = input.trimmed().toInt(&ok);
        if (ok && v > maximum()) {
            if (refused)
                refused(v);
            return QValidator::Invalid;
        }
        return QSpinBox::validate(input, pos);
    }
};

/// A combo box that never truncates its items (in Catalan, in presentation mode): when the
/// side panel is narrow, the form wraps its label above it instead.
class WholeComboBox : public QComboBox {
public:
    using QComboBox::QComboBox;
    QSize minimumSizeHint() const override { return sizeHint(); }
};

/// The view takes in the fitted control points when they lie within this many times the
/// data's size of the data's box (Ex 2.8's P2 lies 1.3 sizes beyond it), so that the data keep
/// at least a seventh of the view; farther off (a high degree: × 10⁶) they are left out.
constexpr double kControlPointReach = 3.0;

/// A fitted value in a label: six significant digits.
QString fittedValueText(double v) { return displaySignificant(v, 6); }

QRectF boundsOf(const std::vector<Point>& a, const std::vector<Point>& b)
{
    const std::optional<PointExtent> box = finiteExtent(a, b);
    if (!box)
        return QRectF(-1, -1, 2, 2);
    double w = box->width(), h = box->height();
    const double size = std::max({w, h, std::fabs(box->minX) * 1e-12, std::fabs(box->minY) * 1e-12, 1e-300});
    if (w < size * 1e-3)
        w = size * 1e-3;
    if (h < size * 1e-3)
        h = size * 1e-3;
    const double cx = 0.5 * box->minX + 0.5 * box->maxX, cy = 0.5 * box->minY + 0.5 * box->maxY;
    return QRectF(cx - 0.5 * w, cy - 0.5 * h, w, h);
}

/// File ▸ Export of the tab: its canvas, once a fit running in the background is done.
class FinishedFitView : public Drawable {
public:
    FinishedFitView(const FitTab* tab, Drawable* canvas) : m_tab(tab), m_canvas(canvas) {}
    QSizeF exportSize() const override { return m_canvas->exportSize(); }
    void render(QPainter& painter, const QRectF& target) override
    {
        m_tab->finishFit();
        m_canvas->render(painter, target);
    }

private:
    const FitTab* m_tab;
    Drawable* m_canvas;
};

} // namespace

FitTab::FitTab(QWidget* parent) : CurveTab(QStringLiteral("fit"), QT_TR_NOOP("Fitting"), parent)
{
    addLayers(); // under the data handles, which the editor draws last
    m_editor = new PointEditor(m_canvas, m_undo, this);
    m_editor->setLabelPrefix(QStringLiteral("Q"));
    m_editor->setPolygonVisible(false);
    m_editor->setCountLimits(2, static_cast<int>(kMaxDataPoints)); // what a document holds, it opens
    m_table = new PointTable(m_editor, this);
    // The table refreshes through updateTable(), which skips huge data sets (10^6 rows would hang).
    disconnect(m_editor, &PointEditor::pointsChanged, m_table, nullptr);
    m_background = new BackgroundFit(this);
    buildUi();

    connect(m_background, &BackgroundFit::finished, this, &FitTab::backgroundFitFinished);
    connect(m_background, &BackgroundFit::progress, this, [this] { updateReadouts(); });
    m_exportView = std::make_unique<FinishedFitView>(this, m_canvas);
    setExportView(m_exportView.get());
    connect(m_editor, &PointEditor::pointsChanged, this, &FitTab::onPointsChanged);
    connect(m_editor, &PointEditor::message, this, &FitTab::statusMessage);
    connect(m_table, &PointTable::message, this, &FitTab::statusMessage);
    connect(m_canvas, &CurveCanvas::cursorMoved, this, [this](double x, double y) {
        if (m_editor->pick(m_canvas->view().toScreen(Point(x, y))) >= 0)
            emit statusMessage(tr("Drag Qᵢ: the curve is refitted as it moves; Delete removes it."));
    });

    // A sensible start: the data of Ex 2.7 with n = 2, uniform parameters (no undo step).
    if (const WorkedExample* example = findWorkedExample("2.7")) {
        m_loading = true;
        m_settings.degree = example->degree;
        m_editor->applyPoints(toDouble(example->points));
        m_loading = false;
    }
    updateControls();
    refit();
    retranslate();
    m_canvas->fitToContent();
}

FitTab::~FitTab() = default; // the background fit, a child, supersedes a fit still running

// ---------------------------------------------------------------- construction

void FitTab::buildUi()
{
    // Settings.
    m_settingsGroup = new QGroupBox(this);
    auto* form = new QFormLayout(m_settingsGroup);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // narrow (presentation, Catalan): labels above the fields
    auto* degree = new DegreeSpinBox(m_settingsGroup);
    degree->refused = [this](int asked) {
        m_refusal = refusalText(asked);
        emit statusMessage(m_refusal);
        updateReadouts();
    };
    m_degree = degree;
    m_degree->setRange(0, kMaxDegree);
    m_degreeLabel = new QLabel(m_settingsGroup);
    m_degreeLabel->setBuddy(m_degree);
    form->addRow(m_degreeLabel, m_degree);
    m_parametrization = new WholeComboBox(m_settingsGroup);
    m_parametrization->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (Parametrization p :
         {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal, Parametrization::AnnexIII})
        m_parametrization->addItem(QString(), static_cast<int>(p));
    m_parametrizationLabel = new QLabel(m_settingsGroup);
    m_parametrizationLabel->setBuddy(m_parametrization);
    form->addRow(m_parametrizationLabel, m_parametrization);
    m_solver = new WholeComboBox(m_settingsGroup);
    m_solver->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (LeastSquaresSolver s : {LeastSquaresSolver::Qr, LeastSquaresSolver::Normal, LeastSquaresSolver::Svd})
        m_solver->addItem(QString(), static_cast<int>(s));
    m_solverLabel = new QLabel(m_settingsGroup);
    m_solverLabel->setBuddy(m_solver);
    form->addRow(m_solverLabel, m_solver);
    m_correct = new QCheckBox(m_settingsGroup);
    m_iterations = new QSpinBox(m_settingsGroup);
    m_iterations->setRange(1, kMaxIterations);
    form->addRow(m_correct, m_iterations);
    auto* buttons = new QHBoxLayout;
    m_import = new QPushButton(m_settingsGroup);
    m_showMatrices = new QCheckBox(m_settingsGroup);
    buttons->addWidget(m_import);
    buttons->addWidget(m_showMatrices);
    buttons->addStretch(1);
    form->addRow(buttons);
    // The comb and its scale, as the correction and its count: a row of their own.
    m_combBox = new QCheckBox(m_settingsGroup);
    m_combScaleBox = new CurvatureCombScaleBox(m_settingsGroup);
    m_combScaleBox->setEnabled(false);
    form->addRow(m_combBox, m_combScaleBox);

    // What is drawn: the thesis's Matlab options (Annex III) and the error plot's lines.
    m_displayGroup = new QGroupBox(this);
    auto* display = new QFormLayout(m_displayGroup);
    display->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    display->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_controlPointsBox = new QCheckBox(m_displayGroup);
    m_residualsBox = new QCheckBox(m_displayGroup);
    m_breakdownBox = new QCheckBox(m_displayGroup);
    m_allParametrizationsBox = new QCheckBox(m_displayGroup);
    m_samplesLabel = new QLabel(m_displayGroup);
    m_samplesBox = new QSpinBox(m_displayGroup);
    m_samplesBox->setRange(FitDisplay::kMinSamples, FitDisplay::kMaxSamples);
    m_samplesBox->setKeyboardTracking(false);
    m_samplesLabel->setBuddy(m_samplesBox);
    auto* toggles = new QHBoxLayout;
    toggles->addWidget(m_controlPointsBox);
    toggles->addWidget(m_residualsBox);
    toggles->addStretch(1);
    display->addRow(toggles);
    display->addRow(m_breakdownBox);
    display->addRow(m_samplesLabel, m_samplesBox);
    display->addRow(m_allParametrizationsBox);
    const auto toggle = [this](QCheckBox* box, bool FitDisplay::*flag, const char* undoText) {
        connect(box, &QCheckBox::toggled, this, [this, flag, undoText](bool on) {
            if (m_updatingControls)
                return;
            FitDisplay after = m_display;
            after.*flag = on;
            changeDisplay(after, tr(undoText));
        });
    };
    toggle(m_controlPointsBox, &FitDisplay::controlPoints, QT_TR_NOOP("Control points"));
    toggle(m_residualsBox, &FitDisplay::residuals, QT_TR_NOOP("Residuals"));
    toggle(m_breakdownBox, &FitDisplay::breakdown, QT_TR_NOOP("Step by step"));
    toggle(m_allParametrizationsBox, &FitDisplay::errorPlotAllParametrizations, QT_TR_NOOP("Every parametrization in the plot"));
    connect(m_samplesBox, qOverload<int>(&QSpinBox::valueChanged), this, [this](int part) {
        if (m_updatingControls)
            return;
        FitDisplay after = m_display;
        after.samples = part;
        changeDisplay(after, tr("Samples: %1").arg(part), kSamplesMergeId);
    });

    // Readouts.
    m_readoutGroup = new QGroupBox(this);
    auto* readouts = new QVBoxLayout(m_readoutGroup);
    for (QLabel** label : {&m_sseLabel, &m_rmsLabel, &m_maxLabel, &m_condLabel, &m_correctionsLabel, &m_warningLabel}) {
        *label = new QLabel(m_readoutGroup);
        (*label)->setTextInteractionFlags(Qt::TextSelectableByMouse);
        (*label)->setWordWrap(true);
        readouts->addWidget(*label);
    }
    m_warningLabel->setObjectName(QStringLiteral("fitWarning"));
    m_warningLabel->setStyleSheet(QStringLiteral("color: #8a3a00;"));
    // A fit in the background: how far it is, and Cancel (hidden otherwise).
    auto* busy = new QHBoxLayout;
    m_progress = new QProgressBar(m_readoutGroup);
    m_progress->setTextVisible(false);
    m_cancel = new QPushButton(m_readoutGroup);
    busy->addWidget(m_progress, 1);
    busy->addWidget(m_cancel);
    readouts->addLayout(busy);
    m_progress->hide();
    m_cancel->hide();
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        m_background->cancel();
        updateReadouts();
    });

    m_exact = new ExactPanel(this);
    m_exact->setMinimumWidth(240);

    auto* side = new QWidget(this);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_settingsGroup);
    sideLayout->addWidget(m_displayGroup);
    sideLayout->addWidget(m_readoutGroup);
    sideLayout->addWidget(m_exact, 1);
    // On a small screen (800×600, presentation mode at 1024×768) the side scrolls rather than squeezing its rows.
    auto* sideArea = new VerticalScrollArea(side, this);

    // The error against the degree.
    m_plot = new QCustomPlot(this);
    m_plot->setMinimumHeight(120);
    keepTickLabelsInside(m_plot);
    setUpFitErrorPlot(m_plot); // Σ‖Q_i − α(t_i)‖² for n = 1..min(k, kMaxFitDegree)
    m_plotText = new QCPItemText(m_plot);
    m_plotText->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_plotText->position->setCoords(0.98, 0.04);
    m_plotText->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
    m_plotText->setTextAlignment(Qt::AlignRight);
    m_plotText->setColor(QColor(0x8a, 0x3a, 0x00)); // the warnings' colour
    m_plotText->setClipToAxisRect(true);
    m_plotText->setVisible(false);

    auto* tableBox = new QWidget(this);
    auto* tableLayout = new QVBoxLayout(tableBox);
    tableLayout->setContentsMargins(0, 0, 0, 0);
    m_tableNote = new QLabel(tableBox);
    m_tableNote->setWordWrap(true);
    m_tableNote->hide();
    tableLayout->addWidget(m_table, 1);
    tableLayout->addWidget(m_tableNote);
    m_table->setMinimumWidth(160);

    m_bottomSplitter = new QSplitter(Qt::Horizontal, this);
    m_bottomSplitter->addWidget(tableBox);
    m_bottomSplitter->addWidget(m_plot);
    m_bottomSplitter->setStretchFactor(0, 1);
    m_bottomSplitter->setStretchFactor(1, 2);
    m_bottomSplitter->setSizes({260, 520});
    m_leftSplitter = new QSplitter(Qt::Vertical, this);
    m_leftSplitter->addWidget(m_canvas);
    m_leftSplitter->addWidget(m_bottomSplitter);
    m_leftSplitter->setStretchFactor(0, 3);
    m_leftSplitter->setStretchFactor(1, 1);
    m_leftSplitter->setSizes({500, 220});
    m_mainSplitter = new QSplitter(Qt::Horizontal, this);
    m_mainSplitter->addWidget(m_leftSplitter);
    m_mainSplitter->addWidget(sideArea);
    setSidePanel(sideArea);
    m_mainSplitter->setStretchFactor(0, 2);
    m_mainSplitter->setStretchFactor(1, 1);
    m_mainSplitter->setSizes({830, 450});
    m_mainSplitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_mainSplitter);

    // Every setting change is an undo step (consecutive ones of the same setting merge).
    connect(m_degree, qOverload<int>(&QSpinBox::valueChanged), this, [this](int n) {
        if (m_updatingControls)
            return;
        FitSettings after = m_settings;
        after.degree = n;
        changeSettings(after, tr("Degree %1").arg(n), DegreeField);
    });
    connect(m_parametrization, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (m_updatingControls || index < 0)
            return;
        FitSettings after = m_settings;
        after.parametrization = static_cast<Parametrization>(m_parametrization->itemData(index).toInt());
        changeSettings(after, tr("Parametrization"), ParametrizationField);
    });
    connect(m_solver, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        if (m_updatingControls || index < 0)
            return;
        FitSettings after = m_settings;
        after.solver = static_cast<LeastSquaresSolver>(m_solver->itemData(index).toInt());
        changeSettings(after, tr("Solver"), SolverField);
    });
    connect(m_correct, &QCheckBox::toggled, this, [this](bool on) {
        if (m_updatingControls)
            return;
        FitSettings after = m_settings;
        after.correctParameters = on;
        changeSettings(after, tr("Parameter correction"), CorrectionField);
    });
    connect(m_iterations, qOverload<int>(&QSpinBox::valueChanged), this, [this](int n) {
        if (m_updatingControls)
            return;
        FitSettings after = m_settings;
        after.iterations = n;
        changeSettings(after, tr("Parameter correction"), CorrectionField);
    });
    connect(m_showMatrices, &QCheckBox::toggled, this, [this](bool on) {
        updateExact();
        emit documentChanged();
        if (m_loading)
            return; // a document's value: no step
        auto apply = [this](bool v) {
            {
                const QSignalBlocker block(m_showMatrices);
                m_showMatrices->setChecked(v);
            }
            updateExact();
            emit documentChanged();
        };
        m_undo->push(new ValueCommand<bool>(apply, !on, on, tr("Show matrices"), -1, {false, /*appliedAlready=*/true}));
    });
    connect(m_combBox, &QCheckBox::toggled, this, [this](bool on) {
        updateComb();
        emit documentChanged();
        if (m_loading)
            return; // a document's value: no step
        auto apply = [this](bool v) {
            {
                const QSignalBlocker block(m_combBox);
                m_combBox->setChecked(v);
            }
            updateComb();
            emit documentChanged();
        };
        m_undo->push(new ValueCommand<bool>(apply, !on, on, tr("Curvature comb"), -1, {false, /*appliedAlready=*/true}));
    });
    connect(m_combScaleBox, &QDoubleSpinBox::valueChanged, this, [this](double scale) {
        const double before = m_combScale;
        m_combScale = scale;
        updateComb();
        emit documentChanged();
        if (m_loading || scale == before)
            return;
        auto apply = [this](double v) {
            m_combScale = v;
            m_combScaleBox->setScale(v);
            updateComb();
            emit documentChanged();
        };
        constexpr int kCombScaleMergeId = 0x46540001; // "FT": a spin box held down is one step
        m_undo->push(new ValueCommand<double>(apply, before, scale, tr("Comb scale"), kCombScaleMergeId, {true, true}));
    });
    connect(m_import, &QPushButton::clicked, this, &FitTab::importDialog);
}

void FitTab::updateComb()
{
    constexpr int kCombSamples = 160;
    m_comb = m_combBox->isChecked() && m_fit ? curvatureComb(m_fit->controlPoints, kCombSamples, m_combScale) : CurvatureComb{};
    m_combScaleBox->setEnabled(m_combBox->isChecked());
    if (m_combScale == 0 && !m_comb.empty())
        m_combScaleBox->setAutomaticScale(m_comb.scale);
    m_canvas->setContentBounds(contentBounds()); // the teeth are in the view (unless the user moved it)
}

void FitTab::addLayers()
{
    // The curvature comb of the fitted curve, under it, with its scale in the key.
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_combBox->isChecked() || m_comb.empty())
            return;
        drawCurvatureComb(p, view, style, m_comb);
        CanvasLegend legend;
        legend.entries.push_back({curvatureCombColor(), Qt::SolidLine,
                                  tr("curvature comb of the fit: teeth |κ| × %1").arg(displaySignificant(m_comb.scale, 6))});
        drawCanvasLegend(p, view, style, legend);
    });
    // The residual segments, then the breakdown, the polygon, the curve and its control points (fit_display.h).
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        drawFitResiduals(p, view, style, {m_editor->points(), currentFit(), m_curve, m_breakdown, m_display});
    });
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        drawFitCurve(p, view, style, {m_editor->points(), currentFit(), m_curve, m_breakdown, m_display});
    });
}

// ---------------------------------------------------------------- texts

void FitTab::retranslate()
{
    m_settingsGroup->setTitle(tr("Least-squares fit (§2.1.3)"));
    m_degreeLabel->setText(tr("&Degree n:"));
    m_degree->setToolTip(tr("n: the fitted Bézier curve has n + 1 control points P₀…Pₙ, so n + 1 ≤ k + 1 data "
                            "points (§2.1.3, Lemma 2.2). Ex 2.7 uses n = 2, Ex 2.8 n = 3."));
    m_parametrizationLabel->setText(tr("&Parameters tᵢ:"));
    m_parametrization->setItemText(0, tr("Uniform, i/k (Ex 2.7, 2.8)"));
    m_parametrization->setItemText(1, tr("Chord length (Ex 2.9, 2.10)"));
    m_parametrization->setItemText(2, tr("Centripetal (beyond the thesis)"));
    m_parametrization->setItemText(3, tr("Annex III (BezParamProp)"));
    m_parametrization->setToolTip(
        tr("Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord "
           "lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); centripetal, proportional to √dᵢ; or as Annex III's BezParamProp "
           "computes them, with |Qᵢ₋₁| in place of dᵢ (how Figs 2.7 and 2.8 were drawn)."));
    m_solverLabel->setText(tr("&Solver:"));
    m_solver->setItemText(0, tr("QR (default)"));
    m_solver->setItemText(1, tr("Normal equations (the thesis)"));
    m_solver->setItemText(2, tr("SVD (singular values)"));
    m_solver->setToolTip(tr("How MP = Q is solved in the least-squares sense. The thesis solves the normal "
                            "equations MᵀM P = MᵀQ (Prop 2.2), which square the condition number; QR and SVD "
                            "work on M itself and stay accurate at high degree."));
    m_correct->setText(tr("&Correct parameters, at most"));
    m_correct->setToolTip(tr("Beyond the thesis: project each Qᵢ onto the fitted curve, take the new tᵢ and fit "
                             "again, while the error Σ‖Qᵢ − α(tᵢ)‖² drops."));
    m_iterations->setSuffix(tr(" times"));
    m_iterations->setToolTip(tr("The largest number of parameter corrections (re-projection and refit)."));
    m_import->setText(tr("&Import CSV…"));
    m_import->setToolTip(tr("Read the data points Qᵢ from a CSV file (one “x,y” per line) or a JSON list [[x,y],…]."));
    m_showMatrices->setText(tr("Show &matrices"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop correcting the parameters: the curve shown is then the best fit found so far."));
    m_combBox->setText(tr("Curvature com&b"));
    m_combBox->setToolTip(
        tr("The curvature comb of the fitted curve (beyond the thesis): teeth along the normal as long "
           "as |κ| times the scale in the key, and the line through their tips; where the comb wiggles, so does the fit."));
    m_combScaleBox->retranslate();
    m_showMatrices->setToolTip(tr("Show M (Lemma 2.2), MᵀM, (MᵀM)⁻¹ and M⁺ = (MᵀM)⁻¹Mᵀ (Note 2.2), in fractions "
                                  "when the data and the parameters are rational, as in Ex 2.7 and Ex 2.8."));
    m_displayGroup->setTitle(tr("Drawing"));
    m_controlPointsBox->setText(tr("Con&trol points"));
    m_controlPointsBox->setToolTip(tr("Draw the fitted control points Pⱼ (squares), their labels and the control "
                                      "polygon. The thesis's Figs 2.5–2.8 show the curve and the data alone."));
    m_residualsBox->setText(tr("&Residuals"));
    m_residualsBox->setToolTip(tr("Draw the segments from α(tᵢ) to each data point Qᵢ: the errors the fit minimises."));
    m_breakdownBox->setText(tr("Step by st&ep"));
    m_breakdownBox->setToolTip(tr("Also draw the Bézier curves of the first 1, 2, …, n+1 fitted control points, thinner "
                                  "and lighter, like the desglossar option of the thesis's Matlab Rep_BezParamEqui and "
                                  "Rep_BezParamProp (Annex III)."));
    m_samplesLabel->setText(tr("Samp&les:"));
    const QString samplesTip = tr("Sampling precision: the fitted curve is drawn through this many intervals of t, like "
                                  "part in the thesis's Matlab Rep_BezParamEqui(Q, n, part, desglossar).");
    m_samplesLabel->setToolTip(samplesTip);
    m_samplesBox->setToolTip(samplesTip);
    m_allParametrizationsBox->setText(tr("Every parametri&zation in the error plot"));
    m_allParametrizationsBox->setToolTip(tr("Plot the error against the degree for uniform, chord-length, centripetal and "
                                            "Annex III parameters at once, one line each, to see where each wins."));
    m_readoutGroup->setTitle(tr("Quality of the fit (Prop 2.2)"));
    m_readoutGroup->setToolTip(tr("The error that the least-squares curve minimises, and how sensitive the "
                                  "solution is to the data."));
    m_canvas->setToolTip(tr("The data points Qᵢ (round, draggable), the fitted Bézier curve α(t), its control "
                            "points Pⱼ (square) and control polygon, and the residuals Qᵢ − α(tᵢ)."));
    m_exact->setToolTip(tr("The parameters, the control points P = M⁺Q and the curve α(t) in powers of t, exact "
                           "when possible (Ex 2.7–2.10)."));
    m_plot->setToolTip(tr("The least-squares error Σ‖Qᵢ − α(tᵢ)‖² of the best curve of each degree n for the "
                          "current parameters (without correction); the circle marks the current n. With fixed "
                          "tᵢ it can only go down as n grows, unless the solver loses accuracy."));
    m_plot->xAxis->setLabel(tr("degree n"));
    m_plot->yAxis->setLabel(tr("squared error (log)"));
    keepAxisTitlesWhole(m_plot);
    m_table->retranslate();
    m_tableNote->setToolTip(tr("Large data sets are fitted and drawn, but not listed."));
    updateTable();
    updateReadouts();
    updateExact();
    updatePlot(); // the key's names
}

QString FitTab::errorText(const Error& error) const
{
    switch (error.code) {
    case ErrorCode::TooFewPoints: return tr("A least-squares fit needs at least 2 data points.");
    case ErrorCode::DegreeTooHigh:
        return tr("Degree %1 needs at least %2 data points.").arg(fittedDegree()).arg(fittedDegree() + 1);
    case ErrorCode::Singular:
        return m_settings.solver == LeastSquaresSolver::Normal
                   ? tr("The normal equations MᵀM P = MᵀQ cannot be solved here: MᵀM is numerically singular "
                        "(coincident points, or cond₂(MᵀM) = cond₂(M)² beyond 10¹⁶). Choose QR or SVD.")
                   : tr("The least-squares system has no usable solution here.");
    case ErrorCode::OutOfRange: return tr("The fitted curve does not fit in double precision: lower the degree.");
    case ErrorCode::InvalidInput:
    default: return tr("A data point is not a finite number.");
    }
}

QString FitTab::refusalText(int asked) const
{
    const int count = static_cast<int>(m_editor->points().size());
    if (asked > kMaxDegree)
        return tr("Degree %1 is refused: the highest is %2, beyond which the Bernstein basis is too "
                  "ill-conditioned for any solver.")
            .arg(asked)
            .arg(kMaxDegree);
    return tr("Degree %1 needs %2 data points (n + 1 ≤ k + 1); there are %3, so n ≤ %4.")
        .arg(asked)
        .arg(asked + 1)
        .arg(count)
        .arg(std::min(count - 1, kMaxDegree));
}

// ---------------------------------------------------------------- settings

int FitTab::fittedDegree() const
{
    const int k = static_cast<int>(m_editor->points().size()) - 1;
    return std::max(0, std::min(m_settings.degree, k));
}

void FitTab::changeSettings(const FitSettings& after, const QString& undoText, int field)
{
    if (after == m_settings)
        return;
    const int mergeId = field < 0 ? -1 : kFieldMergeIdBase + field;
    m_undo->push(new ValueCommand<FitSettings>([this](const FitSettings& s) { applySettings(s); }, m_settings, after, undoText,
                                               mergeId, {/*dropWhenUnchanged=*/true}));
}

void FitTab::applySettings(const FitSettings& s)
{
    m_settings = s;
    updateControls();
    refit();
    emit documentChanged();
}

void FitTab::updateControls()
{
    m_updatingControls = true;
    const int k = static_cast<int>(m_editor->points().size()) - 1;
    m_degree->setMaximum(std::clamp(k, 0, kMaxDegree));
    m_degree->setValue(fittedDegree());
    m_parametrization->setCurrentIndex(m_parametrization->findData(static_cast<int>(m_settings.parametrization)));
    m_solver->setCurrentIndex(m_solver->findData(static_cast<int>(m_settings.solver)));
    m_correct->setChecked(m_settings.correctParameters);
    m_iterations->setValue(std::clamp(m_settings.iterations, 1, kMaxIterations));
    m_iterations->setEnabled(m_settings.correctParameters);
    m_controlPointsBox->setChecked(m_display.controlPoints);
    m_residualsBox->setChecked(m_display.residuals);
    m_breakdownBox->setChecked(m_display.breakdown);
    m_samplesBox->setValue(m_display.samples);
    m_allParametrizationsBox->setChecked(m_display.errorPlotAllParametrizations);
    m_updatingControls = false;
}

// ---------------------------------------------------------------- fitting

void FitTab::onPointsChanged()
{
    const int before = m_lastFittedDegree;
    updateControls();
    refit();
    updateTable();
    if (!m_loading && before >= 0 && fittedDegree() < before && fittedDegree() < m_settings.degree)
        emit statusMessage(tr("Degree lowered to %1: n + 1 control points need at least n + 1 data points, and "
                              "there are %2.")
                               .arg(fittedDegree())
                               .arg(m_editor->points().size()));
    emit documentChanged();
}

void FitTab::refit()
{
    const std::vector<Point>& q = m_editor->points();
    FitOptions options;
    options.degree = fittedDegree();
    options.parametrization = m_settings.parametrization;
    options.solver = m_settings.solver;
    options.correctParameters = m_settings.correctParameters;
    options.maxCorrections = m_settings.iterations;
    m_lastFittedDegree = options.degree;
    m_refusal.clear();
    if (fitWork(q.size(), options.degree, options.correctParameters, options.maxCorrections) > kBackgroundFitWork) {
        // Long: on a worker thread, superseding any fit still running there. Until it is
        // done the tab shows no curve (not the last one, which belongs to other data) and
        // says it is fitting.
        m_fit.reset();
        m_fitError.clear();
        resample();
        m_background->start(q, options);
        updateFitViews();
    } else {
        m_background->supersede(); // this quick fit is the newest
        showFit(fitBezier(q, options));
    }
    updatePlot();
}

void FitTab::showFit(Expected<FitResult> fit)
{
    if (fit) {
        m_fit = std::move(fit).value();
        m_fitError.clear();
    } else {
        m_fit.reset();
        m_fitError = errorText(fit.error());
    }
    resample();
    updateFitViews();
}

void FitTab::resample()
{
    m_curve = m_fit ? sampleBezier(m_fit->controlPoints, m_display.samples + 1) : std::vector<Point>{};
    m_breakdown = m_fit && m_display.breakdown ? breakdownCurves(m_fit->controlPoints, m_display.samples)
                                               : std::vector<std::vector<Point>>{};
}

void FitTab::changeDisplay(const FitDisplay& after, const QString& undoText, int mergeId)
{
    if (after == m_display)
        return;
    m_undo->push(new ValueCommand<FitDisplay>([this](const FitDisplay& d) { applyDisplay(d); }, m_display, after, undoText,
                                              mergeId, {/*dropWhenUnchanged=*/true}));
}

void FitTab::applyDisplay(const FitDisplay& d)
{
    const FitDisplay before = m_display;
    m_display = d;
    updateControls();
    if (d.samples != before.samples || d.breakdown != before.breakdown)
        resample();
    if (d.errorPlotAllParametrizations != before.errorPlotAllParametrizations)
        updatePlot();
    m_canvas->update();
    emit documentChanged();
}

QCPGraph* FitTab::errorGraph(Parametrization p) const
{
    return fitErrorGraph(m_plot, p, m_settings.parametrization, m_display.errorPlotAllParametrizations);
}

void FitTab::updateFitViews()
{
    updateComb();
    m_canvas->setContentBounds(contentBounds());
    m_canvas->update();
    updateReadouts();
    updateExact();
}

void FitTab::backgroundFitFinished()
{
    showFit(m_background->takeResult());
    if (m_fit && m_fit->cancelled)
        emit statusMessage(tr("Fit cancelled: the curve shown is the best fit found so far."));
    emit backgroundFitShown();
}

bool FitTab::isFitting() const { return m_background->running(); }

void FitTab::finishFit() const { m_background->finish(); }

QRectF FitTab::contentBounds() const
{
    // The view shows the data and the curve; the control points when they are shown, unless
    // they fly far off (high degrees put them orders of magnitude away: then the data would
    // shrink to a dot); and the comb's teeth when it is shown (curvature_comb.h keeps them
    // within half the curve's size of it).
    const QRectF data = boundsOf(m_editor->points(), m_curve);
    QRectF bounds = data;
    if (m_fit && m_display.controlPoints) {
        const QRectF control = boundsOf(m_fit->controlPoints, {});
        const double size = std::max(data.width(), data.height());
        const double reach = kControlPointReach * size;
        if (data.adjusted(-reach, -reach, reach, reach).contains(control))
            bounds = bounds.united(control);
    }
    if (m_combBox && m_combBox->isChecked() && !m_comb.empty()) {
        std::vector<Point> tips;
        for (const CurvatureComb::Tooth& tooth : m_comb.teeth)
            tips.push_back(tooth.tip);
        bounds = bounds.united(boundsOf(tips, {}));
    }
    return bounds;
}

void FitTab::updateReadouts()
{
    if (!m_sseLabel)
        return;
    const std::vector<Point>& q = m_editor->points();
    QStringList warnings;
    if (!m_refusal.isEmpty())
        warnings << m_refusal;
    const bool fitting = m_background->running();
    m_progress->setVisible(fitting);
    m_cancel->setVisible(fitting);
    if (fitting) {
        const int done = m_background->correctionsDone(), allowed = m_background->correctionsAllowed();
        m_progress->setRange(0, std::max(allowed, 0)); // 0 … 0: busy, with no count
        m_progress->setValue(std::min(done, allowed));
        m_cancel->setEnabled(!m_background->cancelling() && allowed > 0);
        if (m_background->cancelling())
            m_sseLabel->setText(tr("Cancelling: the fit stops after the correction under way…"));
        else if (allowed > 0)
            m_sseLabel->setText(
                tr("Fitting in the background: %1 of at most %2 parameter corrections made…").arg(done).arg(allowed));
        else
            m_sseLabel->setText(tr("Fitting in the background…"));
        m_rmsLabel->clear();
        m_maxLabel->clear();
        m_condLabel->clear();
        m_correctionsLabel->hide();
    } else if (m_fit) {
        m_sseLabel->setText(tr("Squared error Σ‖Qᵢ − α(tᵢ)‖²: %1").arg(fittedValueText(m_fit->sse)));
        m_rmsLabel->setText(tr("RMS error √(Σ/(k+1)): %1").arg(fittedValueText(m_fit->rms)));
        m_maxLabel->setText(tr("Largest error max‖Qᵢ − α(tᵢ)‖: %1").arg(fittedValueText(m_fit->maxError)));
        m_condLabel->setText(m_fit->cond >= std::numeric_limits<double>::max()
                                 ? tr("Condition number cond₂(M): infinite (M is singular)")
                                 : tr("Condition number cond₂(M): %1").arg(fittedValueText(m_fit->cond)));
        m_correctionsLabel->setVisible(m_settings.correctParameters);
        m_correctionsLabel->setText(tr("Parameter corrections that lowered the error: %1").arg(m_fit->corrections));
        if (m_fit->cancelled)
            warnings << tr("Cancelled after %1 of at most %2 parameter corrections: the curve shown is the best fit "
                           "found until then.")
                            .arg(m_fit->corrections)
                            .arg(m_settings.iterations);
    } else {
        m_sseLabel->setText(tr("No fit: %1").arg(m_fitError));
        m_rmsLabel->clear();
        m_maxLabel->clear();
        m_condLabel->clear();
        m_correctionsLabel->hide();
    }
    m_rmsLabel->setVisible(m_fit.has_value());
    m_maxLabel->setVisible(m_fit.has_value());
    // The canvas, for screen readers: the degree, the data and the error.
    canvas()->setAccessibleName(tr("Fitting canvas"));
    canvas()->setAccessibleDescription(
        fitting ? m_sseLabel->text()
        : m_fit ? tr("Least-squares Bézier curve of degree %1 through %n data point(s); squared error %2.", nullptr,
                     static_cast<int>(q.size()))
                      .arg(m_settings.degree)
                      .arg(fittedValueText(m_fit->sse))
                : tr("No fit: %1").arg(m_fitError));
    m_condLabel->setVisible(m_fit.has_value());
    // The core decides what to warn about (fit_warning.h); the tab only words it.
    FitOptions options;
    options.degree = fittedDegree();
    options.parametrization = m_settings.parametrization;
    options.solver = m_settings.solver;
    for (const FitWarning& w : fitWarnings(m_fit ? &*m_fit : nullptr, q, options)) {
        switch (w.code) {
        case FitWarningCode::IllConditioned:
            warnings << tr("⚠ Ill-conditioned: cond₂(M) ≈ %1. The control points are very sensitive to the data; "
                           "lower the degree.")
                            .arg(fittedValueText(w.cond));
            break;
        case FitWarningCode::HighDegree:
            warnings << tr("⚠ High degree n = %1: the Bernstein basis grows ill-conditioned (cond₂(M) ≈ %2); a "
                           "lower degree or a spline is usually the better model.")
                            .arg(w.degree)
                            .arg(fittedValueText(w.cond));
            break;
        case FitWarningCode::NormalEquationsSquare:
            warnings << tr("⚠ The normal equations square the condition number: cond₂(MᵀM) ≈ %1, so about %2 of "
                           "the 16 significant digits may be lost. Choose QR.")
                            .arg(fittedValueText(w.cond * w.cond))
                            .arg(normalEquationsDigitsLost(w.cond));
            break;
        case FitWarningCode::RepeatedParameters:
            warnings << tr("⚠ Only %1 distinct parameters tᵢ for %2 control points: M is rank deficient, and the "
                           "control points shown are the minimum-norm least-squares solution.")
                            .arg(w.distinct)
                            .arg(w.degree + 1);
            break;
        case FitWarningCode::AllCoincide:
            warnings << (w.byDistance ? tr("All the data points coincide: the chord lengths are all zero, so uniform "
                                           "parameters are used instead.")
                                      : tr("All the data points coincide: the curve is that point."));
            break;
        case FitWarningCode::ZeroChords:
            warnings << tr("Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such "
                           "pair(s)).",
                           nullptr, w.pairs)
                            .arg(w.first - 1)
                            .arg(w.first);
            break;
        case FitWarningCode::Collinear:
            warnings << tr("The data points are collinear: the fitted curve and its control points lie on their line.");
            break;
        case FitWarningCode::CoincidentFallback:
        case FitWarningCode::CorrectionStopped:
        case FitWarningCode::RankDeficient: break; // fitBezier's notes for the CLI; fitWarnings() does not list them
        }
    }
    m_warningLabel->setText(warnings.join(QLatin1Char('\n')));
    m_warningLabel->setVisible(!warnings.isEmpty());
}

void FitTab::updatePlot()
{
    if (!m_plot)
        return;
    const std::vector<Point>& q = m_editor->points();
    // Every degree allowed, unless that would be too much work to redo on each change (four
    // times the work with every parametrization: the same budget goes to fewer degrees).
    const int highest = std::clamp(static_cast<int>(q.size()) - 1, 0, kMaxDegree);
    const double lines = m_display.errorPlotAllParametrizations ? static_cast<double>(kPlottedParametrizations.size()) : 1.0;
    int plotted = 0;
    for (double work = 0; plotted < highest; ++plotted) {
        work += lines * static_cast<double>(q.size()) * (plotted + 2) * (plotted + 2);
        if (work > kPlotWorkBudget)
            break;
    }
    FitErrorPlotInput in;
    in.points = &q;
    in.parametrization = m_settings.parametrization;
    in.solver = m_settings.solver;
    in.currentDegree = fittedDegree();
    in.lastDegree = plotted;
    m_plotLastDegree = plotted;
    in.allParametrizations = m_display.errorPlotAllParametrizations;
    in.names = {tr("uniform"), tr("chord length"), tr("centripetal"), tr("Annex III")};
    const FitErrorPlotRange shown = fillFitErrorPlot(m_plot, in);
    // Where the plot stops short of the highest degree allowed, it says why, on the plot; the
    // degree it names is the one where the plot's axis ends (shown.lastDegree, failed or not).
    QStringList note;
    if (shown.lastDegree > 0 && shown.lastDegree < highest)
        note << tr("Plotted up to n = %1 of %2:\nrefitting every degree for %3 points\non each change would slow the window.")
                    .arg(shown.lastDegree)
                    .arg(highest)
                    .arg(q.size());
    if (shown.failedDegrees > 0)
        note << tr("%n degree(s) left blank: the fit failed there.\nChoose QR or SVD.", nullptr, shown.failedDegrees);
    m_plotNote = note.join(QLatin1Char('\n'));
    m_plotText->setText(m_plotNote);
    m_plotText->setVisible(!m_plotNote.isEmpty());
    m_plot->replot(QCustomPlot::rpQueuedReplot); // not now: a synchronous repaint would flush the canvas too
}

QString FitTab::plotNote() const { return m_plotNote; }

void FitTab::updateExact()
{
    if (!m_exact)
        return;
    FitExactView::Input in;
    in.points = &m_editor->points();
    in.degree = fittedDegree();
    in.parametrization = m_settings.parametrization;
    in.correctParameters = m_settings.correctParameters;
    in.fit = currentFit();
    in.showMatrices = m_showMatrices->isChecked();
    QString html = FitExactView::html(in);
    if (!m_fit && !m_fitError.isEmpty())
        html += ExactPanel::note(m_fitError);
    m_exact->setContent(html);
}

void FitTab::updateTable()
{
    if (!m_table)
        return;
    const std::size_t count = m_editor->points().size();
    const bool listed = count <= static_cast<std::size_t>(kTableLimit);
    if (listed) {
        m_table->retranslate(); // refreshes the rows
    } else if (m_table->rowCount() != 0) {
        m_table->setRowCount(0);
    }
    m_table->setEnabled(listed);
    m_tableNote->setVisible(!listed);
    m_tableNote->setText(tr("%n data points: too many to list; they are fitted and drawn.", nullptr,
                            static_cast<int>(std::min<std::size_t>(count, std::numeric_limits<int>::max()))));
}

QString FitTab::readoutText() const
{
    QStringList lines;
    for (const QLabel* label : {m_sseLabel, m_rmsLabel, m_maxLabel, m_condLabel})
        if (!label->text().isEmpty())
            lines << label->text();
    return lines.join(QLatin1Char('\n'));
}

QString FitTab::warningText() const { return m_warningLabel->isVisibleTo(this) ? m_warningLabel->text() : QString(); }

// ---------------------------------------------------------------- examples and files

bool FitTab::loadExample(const granota::WorkedExample& example)
{
    if (example.kind != "fit" || example.points.size() < 2)
        return false;
    const std::optional<Parametrization> p = parseParametrization(example.parametrization);
    FitSettings after = m_settings;
    after.degree = std::clamp(example.degree, 0, kMaxDegree);
    after.parametrization = p.value_or(Parametrization::Uniform);
    after.solver = LeastSquaresSolver::Qr;
    after.correctParameters = false;
    const QString id = QString::fromStdString(example.id);
    m_loading = true;
    m_undo->beginMacro(tr("Load Ex %1").arg(id));
    m_editor->setPoints(toDouble(example.points), tr("Ex %1 data").arg(id));
    m_undo->push(new ValueCommand<FitSettings>([this](const FitSettings& s) { applySettings(s); }, m_settings, after,
                                               tr("Ex %1 settings").arg(id)));
    m_undo->endMacro();
    m_loading = false;
    m_canvas->fitToContent();
    return true;
}

bool FitTab::importFile(const QString& path, QString* error)
{
    const QString name = QFileInfo(path).fileName();
    const std::optional<QByteArray> bytes = readUserFile(path, error);
    if (!bytes)
        return false;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const Expected<std::vector<RPoint>> parsed = parsePointFile(
        std::string_view(bytes->constData(), static_cast<std::size_t>(bytes->size())));
    QApplication::restoreOverrideCursor();
    if (!parsed) {
        *error = tr("“%1” holds no valid data points, nothing was changed: %2").arg(name, ErrorText::of(parsed.error()));
        return false;
    }
    if (parsed->size() < 2) {
        *error = tr("“%1” has %n point(s); a fit needs at least 2, nothing was changed.", nullptr,
                    static_cast<int>(parsed->size()))
                     .arg(name);
        return false;
    }
    const std::vector<Point> points = toDouble(*parsed);
    if (!std::all_of(points.begin(), points.end(), [](const Point& p) { return isFinite(p); })) {
        *error = tr("“%1” has a coordinate too large for a double; nothing was changed.").arg(name);
        return false;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    m_editor->setPoints(points, tr("Import %1").arg(name));
    QApplication::restoreOverrideCursor();
    m_canvas->fitToContent();
    QString imported = tr("Imported %n data points from “%1”.", nullptr, static_cast<int>(points.size())).arg(name);
    if (const QString note = m_editor->labelsHiddenNote(); !note.isEmpty())
        imported += QLatin1Char(' ') + note; // the editor said so first: this message replaces that one
    emit statusMessage(imported);
    return true;
}

void FitTab::importDialog()
{
    const QString path = openFileName(this, tr("Import data points"), tr("Point files (*.csv *.txt *.json);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!importFile(path, &error)) {
        emit statusMessage(error);
        QMessageBox::warning(this, tr("Import data points"), error);
    }
}

void FitTab::writeSettings(QJsonObject& state) const
{
    state.insert(QStringLiteral("degree"), m_settings.degree);
    state.insert(QStringLiteral("parametrization"), QString::fromStdString(toString(m_settings.parametrization)));
    state.insert(QStringLiteral("solver"), QString::fromStdString(toString(m_settings.solver)));
    state.insert(QStringLiteral("correctParameters"), m_settings.correctParameters);
    state.insert(QStringLiteral("iterations"), m_settings.iterations);
    state.insert(QStringLiteral("showMatrices"), m_showMatrices->isChecked());
    state.insert(QStringLiteral("curvatureComb"), m_combBox->isChecked());
    state.insert(QStringLiteral("curvatureCombScale"), m_combScale);
    writeFitDisplay(m_display, state);
}

PointListMessages FitTab::pointMessages() const
{
    PointListMessages say;
    say.notAList = tr("The fitting tab's data points are missing or not a list.");
    say.badCount = [](int count) {
        return tr("The fitting tab holds %1 data points; Granota reads at most %2.").arg(count).arg(kMaxDataPoints);
    };
    say.notAPair = [](int i) { return tr("Data point Q%1 is not a pair of finite numbers.").arg(i); };
    say.tooFewAfterPoints = [] { return tr("The fitting tab needs at least 2 data points."); };
    return say;
}

bool FitTab::loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error)
{
    // The points are checked: now the settings, all or nothing.
    FitSettings s;
    const QJsonValue degree = state.value(QStringLiteral("degree"));
    if (!degree.isUndefined()) {
        const double d = degree.toDouble(-1);
        if (!degree.isDouble() || d != std::floor(d) || d < 0 || d > kMaxDegree) {
            error = tr("The degree must be a whole number from 0 to %1.").arg(kMaxDegree);
            return false;
        }
        s.degree = static_cast<int>(d);
    }
    const QJsonValue param = state.value(QStringLiteral("parametrization"));
    if (!param.isUndefined()) {
        const auto p = parseParametrization(param.toString().toStdString());
        if (!p) {
            error = tr("Unknown parametrization “%1”.").arg(param.toVariant().toString());
            return false;
        }
        s.parametrization = *p;
    }
    const QJsonValue solver = state.value(QStringLiteral("solver"));
    if (!solver.isUndefined()) {
        const auto p = parseLeastSquaresSolver(solver.toString().toStdString());
        if (!p) {
            error = tr("Unknown solver “%1”.").arg(solver.toVariant().toString());
            return false;
        }
        s.solver = *p;
    }
    const QJsonValue correct = state.value(QStringLiteral("correctParameters"));
    if (!correct.isUndefined() && !correct.isBool()) {
        error = tr("“correctParameters” must be true or false.");
        return false;
    }
    s.correctParameters = correct.toBool(false);
    const QJsonValue iterations = state.value(QStringLiteral("iterations"));
    if (!iterations.isUndefined()) {
        const double d = iterations.toDouble(-1);
        if (!iterations.isDouble() || d != std::floor(d) || d < 1 || d > kMaxIterations) {
            error = tr("The number of parameter corrections must be a whole number from 1 to %1.").arg(kMaxIterations);
            return false;
        }
        s.iterations = static_cast<int>(d);
    }
    const QJsonValue matrices = state.value(QStringLiteral("showMatrices"));
    if (!matrices.isUndefined() && !matrices.isBool()) {
        error = tr("“showMatrices” must be true or false.");
        return false;
    }
    const QJsonValue comb = state.value(QStringLiteral("curvatureComb")); // older documents: off
    if (!comb.isUndefined() && !comb.isBool()) {
        error = tr("“curvatureComb” must be true or false.");
        return false;
    }
    QString badKey;
    const std::optional<FitDisplay> display = readFitDisplay(state, &badKey); // older documents: as before the keys
    if (!display) {
        error =
            badKey == QLatin1String("samples")
                ? tr("“samples” must be a whole number from %1 to %2.").arg(FitDisplay::kMinSamples).arg(FitDisplay::kMaxSamples)
                : tr("“%1” must be true or false.").arg(badKey);
        return false;
    }
    const QJsonValue combScale = state.value(QStringLiteral("curvatureCombScale")); // older documents: automatic
    if (!combScale.isUndefined() && (!combScale.isDouble() || !std::isfinite(combScale.toDouble()) || combScale.toDouble() < 0 ||
                                     combScale.toDouble() > CurvatureCombScaleBox::kMaxScale)) {
        error = tr("“curvatureCombScale” must be 0 (automatic) or a positive number up to %1.")
                    .arg(displayNumber(CurvatureCombScaleBox::kMaxScale));
        return false;
    }

    // Apply without an undo step: opening a document starts a new history (the main window
    // clears the stacks), and a refused document must leave the user's history as it was.
    m_loading = true;
    m_settings = s;
    m_display = *display;
    m_editor->applyPoints(points); // refits once, with the new settings and drawing
    m_showMatrices->setChecked(matrices.toBool(false));
    m_combScale = combScale.toDouble(0.0);
    m_combScaleBox->setScale(m_combScale);
    m_combBox->setChecked(comb.toBool(false));
    updateComb(); // the scale, also when the toggle did not change
    m_loading = false;
    return true;
}

QString FitTab::csv() const
{
    finishFit(); // the finished fit, never a half state
    const std::vector<Point>& q = m_editor->points();
    // At most 15 significant digits: the data as typed, the fit without binary noise
    // (0.157142857142857, not 0.15714285714285747 beside the panel's 11/70).
    const auto f = [](double v) { return QString::fromStdString(formatReadable(v)); };
    QString out = QStringLiteral("i,x,y,t,alpha_x,alpha_y,residual_x,residual_y\n");
    out.reserve(static_cast<qsizetype>(q.size()) * 160);
    const bool fitted = m_fit && m_fit->residuals.size() == q.size();
    for (std::size_t i = 0; i < q.size(); ++i) {
        out += QStringLiteral("%1,%2,%3").arg(i).arg(f(q[i].x), f(q[i].y));
        if (fitted) {
            const Point r = m_fit->residuals[i];
            const Point a = q[i] - r;
            out += QStringLiteral(",%1,%2,%3,%4,%5").arg(f(m_fit->params[i]), f(a.x), f(a.y), f(r.x), f(r.y));
        } else {
            out += QStringLiteral(",,,,,");
        }
        out += QLatin1Char('\n');
    }
    if (fitted) {
        out += QStringLiteral("\nj,P_x,P_y\n");
        for (std::size_t j = 0; j < m_fit->controlPoints.size(); ++j)
            out += QStringLiteral("%1,%2,%3\n").arg(j).arg(f(m_fit->controlPoints[j].x), f(m_fit->controlPoints[j].y));
    }
    if (m_display.errorPlotAllParametrizations) {
        // The error plot's lines, as fitErrorByDegree gives them (empty where that fit failed).
        out += QStringLiteral("\nparametrization,degree,sse\n");
        FitOptions options;
        options.solver = m_settings.solver;
        for (Parametrization p : kPlottedParametrizations) {
            options.parametrization = p;
            for (const DegreeError& e : fitErrorByDegree(q, options, m_plotLastDegree))
                out += QStringLiteral("%1,%2,%3\n")
                           .arg(QString::fromStdString(toString(p)))
                           .arg(e.degree)
                           .arg(e.ok ? f(e.sse) : QString());
        }
    }
    return out;
}

void FitTab::drawTikz(TikzWriter& tikz) const
{
    finishFit(); // the finished fit, never a half state
    const std::vector<Point>& q = m_editor->points();
    tikz.comment(QStringLiteral("Granota: least-squares Bézier fit of degree %1 (%2 parameters), %3 data points")
                     .arg(fittedDegree())
                     .arg(QString::fromStdString(toString(m_settings.parametrization)))
                     .arg(q.size()));
    writeFitTikz(tikz, {q, currentFit(), m_curve, m_breakdown, m_display}, m_combBox->isChecked() ? &m_comb : nullptr);
}

// ---------------------------------------------------------------- view

void FitTab::presentationChanged(bool on)
{
    const double scale = presentationScale(on);
    const QFont tickFont; // the application's font, which presentation mode enlarges
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        axis->setTickLabelFont(tickFont);
        axis->setLabelFont(tickFont);
    }
    keepAxisTitlesWhole(m_plot);
    styleFitErrorPlot(m_plot, scale);
    m_plot->replot();
    // Shares, not pixels (QSplitter scales them to its size, laid out or not): the side panel's
    // texts grow with the font, so it gets more of the width when the drawer is open
    // (MainWindow::setSidePanelsShown); the canvas keeps two thirds of the height.
    m_mainSplitter->setSizes({on ? 5200 : 6500, on ? 4800 : 3500});
    m_leftSplitter->setSizes({on ? 6600 : 7000, on ? 3400 : 3000});
    m_canvas->fitToContent();
}

QString FitTab::hint() const
{
    return tr("Drag a data point Qᵢ and the curve is refitted; double-click adds a point, Delete "
              "removes it.");
}

} // namespace granota::ui
