#include "ui/fit/fit_tab.h"
#include "ui/common/error_text.h"
#include "ui/fit/background_fit.h"
#include "ui/common/canvas_legend.h"
#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/number_text.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/base/input_limits.h"
#include "core/io/point_list.h"
#include "core/io/worked_examples.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/drawable.h"
#include "ui/common/exact_panel.h"
#include "ui/fit/fit_degree_box.h"
#include "ui/fit/fit_document.h"
#include "ui/fit/fit_drawing_panel.h"
#include "ui/fit/fit_error_plot.h"
#include "ui/fit/fit_export.h"
#include "ui/fit/fit_readout_panel.h"
#include "ui/fit/fit_settings_panel.h"
#include "ui/fit/fit_view_bounds.h"
#include "ui/fit/fit_exact_view.h"
#include "ui/common/point_editor.h"
#include "ui/common/plot_tick_room.h"
#include "ui/common/point_table.h"
#include "ui/common/plot_title_room.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/vertical_scroll_area.h"
#include "ui/common/value_command.h"
#include "ui/files/file_dialogs.h"
#include "ui/files/tikz_writer.h"
#include "ui/files/user_file.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QUndoStack>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

namespace {
/// Undo-merge fields of the settings' ValueCommand (changes of the same field merge).
enum Field { DegreeField, ParametrizationField, SolverField, CorrectionField };
constexpr int kFieldMergeIdBase = 0x46490000; ///< "FI": the merge id of field f is this + f

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
    m_exportView = std::make_unique<FinishedFitView>([this] { finishFit(); }, m_canvas);
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
        m_editor->applyPoints(toDouble(example->points), exactForms(example->points));
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
    m_settingsPanel = new FitSettingsPanel(this);
    m_settingsPanel->degreeBox()->refused = [this](int asked) {
        m_refusal = FitReadoutPanel::refusalText(asked, static_cast<int>(m_editor->points().size()));
        emit statusMessage(m_refusal);
        updateReadouts();
    };
    m_degree = m_settingsPanel->degreeBox();
    m_parametrization = m_settingsPanel->parametrizationBox();
    m_solver = m_settingsPanel->solverBox();
    m_correct = m_settingsPanel->correctionBox();
    m_iterations = m_settingsPanel->iterationsBox();
    m_showMatrices = m_settingsPanel->showMatricesBox();
    m_combBox = m_settingsPanel->combBox();
    m_combScaleBox = m_settingsPanel->combScaleBox();

    // What is drawn: the thesis's Matlab options (Annex III) and the error plot's lines.
    m_drawing = new FitDrawingPanel(
        [this]() -> const FitDisplay& { return m_display; },
        [this](const FitDisplay& after, const QString& undoText, int mergeId) { changeDisplay(after, undoText, mergeId); }, this);

    // Readouts.
    m_readouts = new FitReadoutPanel(this);
    connect(m_readouts->cancelButton(), &QPushButton::clicked, this, [this] {
        m_background->cancel();
        updateReadouts();
    });

    m_exact = new ExactPanel(this);
    m_exact->setMinimumWidth(240);

    auto* side = new QWidget(this);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_settingsPanel);
    sideLayout->addWidget(m_drawing);
    sideLayout->addWidget(m_readouts);
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
    connect(m_settingsPanel->importButton(), &QPushButton::clicked, this, &FitTab::importDialog);
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
    m_settingsPanel->retranslate();
    m_drawing->retranslate();
    m_readouts->retranslate();
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
    m_settingsPanel->showSettings(m_settings, static_cast<int>(m_editor->points().size()) - 1, fittedDegree());
    m_drawing->setDisplay(m_display);
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
        m_fitError = FitReadoutPanel::errorText(fit.error(), fittedDegree(), m_settings.solver);
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
    const bool comb = m_combBox && m_combBox->isChecked();
    return fitViewBounds(m_editor->points(), m_curve, m_fit && m_display.controlPoints ? &m_fit->controlPoints : nullptr,
                         comb ? &m_comb : nullptr);
}

void FitTab::updateReadouts()
{
    if (!m_readouts)
        return;
    FitReadoutPanel::State state;
    state.points = &m_editor->points();
    state.fit = currentFit();
    state.fitError = m_fitError;
    state.refusal = m_refusal;
    state.settings = &m_settings;
    state.fittedDegree = fittedDegree();
    state.fitting = m_background->running();
    state.cancelling = m_background->cancelling();
    state.correctionsDone = m_background->correctionsDone();
    state.correctionsAllowed = m_background->correctionsAllowed();
    m_readouts->showState(state);
    // The canvas, for screen readers: the degree, the data and the error.
    canvas()->setAccessibleName(tr("Fitting canvas"));
    canvas()->setAccessibleDescription(
        state.fitting ? m_readouts->headline()
        : m_fit       ? tr("Least-squares Bézier curve of degree %1 through %n data point(s); squared error %2.", nullptr,
                           static_cast<int>(state.points->size()))
                      .arg(m_settings.degree)
                      .arg(fittedValueText(m_fit->sse))
                : tr("No fit: %1").arg(m_fitError));
}

void FitTab::updatePlot()
{
    if (!m_plot)
        return;
    const std::vector<Point>& q = m_editor->points();
    // Every degree allowed, unless that would be too much work to redo on each change (four
    // times the work with every parametrization: the same budget goes to fewer degrees).
    const int highest = std::clamp(static_cast<int>(q.size()) - 1, 0, kMaxFitDegree);
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
    in.exact = m_editor->allExactPoints();
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

QString FitTab::readoutText() const { return m_readouts->readoutText(); }

QString FitTab::warningText() const { return m_readouts->warningText(); }

QPushButton* FitTab::cancelButton() const { return m_readouts->cancelButton(); }

QProgressBar* FitTab::fitProgress() const { return m_readouts->progressBar(); }

// ---------------------------------------------------------------- examples and files

bool FitTab::loadExample(const granota::WorkedExample& example)
{
    if (example.kind != "fit" || example.points.size() < 2)
        return false;
    const std::optional<Parametrization> p = parseParametrization(example.parametrization);
    FitSettings after = m_settings;
    after.degree = std::clamp(example.degree, 0, kMaxFitDegree);
    after.parametrization = p.value_or(Parametrization::Uniform);
    after.solver = LeastSquaresSolver::Qr;
    after.correctParameters = false;
    const QString id = QString::fromStdString(example.id);
    m_loading = true;
    m_undo->beginMacro(tr("Load Ex %1").arg(id));
    m_editor->setPoints(toDouble(example.points), exactForms(example.points), tr("Ex %1 data").arg(id));
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
    m_editor->setPoints(points, exactForms(*parsed), tr("Import %1").arg(name)); // the values as the file writes them
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
    FitDocument doc;
    doc.settings = m_settings;
    doc.display = m_display;
    doc.showMatrices = m_showMatrices->isChecked();
    doc.curvatureComb = m_combBox->isChecked();
    doc.combScale = m_combScale;
    doc.write(state);
}

PointListMessages FitTab::pointMessages() const { return FitDocument::pointMessages(); }

bool FitTab::loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error)
{
    // The points are checked: now the settings, all or nothing.
    const std::optional<FitDocument> doc = FitDocument::read(state, error);
    if (!doc)
        return false;

    // Apply without an undo step: opening a document starts a new history (the main window
    // clears the stacks), and a refused document must leave the user's history as it was.
    m_loading = true;
    m_settings = doc->settings;
    m_display = doc->display;
    m_editor->applyPoints(points); // refits once, with the new settings and drawing
    m_showMatrices->setChecked(doc->showMatrices);
    m_combScale = doc->combScale;
    m_combScaleBox->setScale(m_combScale);
    m_combBox->setChecked(doc->curvatureComb);
    updateComb(); // the scale, also when the toggle did not change
    m_loading = false;
    return true;
}

QString FitTab::csv() const
{
    finishFit(); // the finished fit, never a half state
    return fitCsv({m_editor->points(), m_editor->exactPoints(), currentFit(), m_display.errorPlotAllParametrizations,
                   m_settings.solver, m_plotLastDegree});
}

void FitTab::drawTikz(TikzWriter& tikz) const
{
    finishFit(); // the finished fit, never a half state
    writeFitFigureTikz(tikz, fittedDegree(), m_settings.parametrization,
                       {m_editor->points(), currentFit(), m_curve, m_breakdown, m_display},
                       m_combBox->isChecked() ? &m_comb : nullptr);
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
