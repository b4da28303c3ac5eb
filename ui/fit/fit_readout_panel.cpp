#include "ui/fit/fit_readout_panel.h"

#include "core/curves/fitting/fit_warning.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace granota::ui {

QString fittedValueText(double v) { return displaySignificant(v, 6); }

FitReadoutPanel::FitReadoutPanel(QWidget* parent) : QGroupBox(parent)
{
    auto* readouts = new QVBoxLayout(this);
    for (QLabel** label : {&m_sseLabel, &m_rmsLabel, &m_maxLabel, &m_condLabel, &m_correctionsLabel, &m_warningLabel}) {
        *label = new QLabel(this);
        (*label)->setTextInteractionFlags(Qt::TextSelectableByMouse);
        (*label)->setWordWrap(true);
        readouts->addWidget(*label);
    }
    m_warningLabel->setObjectName(QStringLiteral("fitWarning"));
    m_warningLabel->setStyleSheet(QStringLiteral("color: #8a3a00;"));
    // A fit in the background: how far it is, and Cancel (hidden otherwise).
    auto* busy = new QHBoxLayout;
    m_progress = new QProgressBar(this);
    m_progress->setTextVisible(false);
    m_cancel = new QPushButton(this);
    busy->addWidget(m_progress, 1);
    busy->addWidget(m_cancel);
    readouts->addLayout(busy);
    m_progress->hide();
    m_cancel->hide();
}

void FitReadoutPanel::retranslate()
{
    setTitle(QCoreApplication::translate("granota::ui::FitTab", "Quality of the fit (Prop 2.2)"));
    setToolTip(QCoreApplication::translate("granota::ui::FitTab",
                                           "The error that the least-squares curve minimises, and how sensitive the "
                                           "solution is to the data."));
    m_cancel->setText(QCoreApplication::translate("granota::ui::FitTab", "Cancel"));
    m_cancel->setToolTip(QCoreApplication::translate(
        "granota::ui::FitTab", "Stop correcting the parameters: the curve shown is then the best fit found so far."));
}

void FitReadoutPanel::showState(const State& state)
{
    const FitResult* fit = state.fit;
    const FitSettings& settings = *state.settings;
    QStringList warnings;
    if (!state.refusal.isEmpty())
        warnings << state.refusal;
    m_progress->setVisible(state.fitting);
    m_cancel->setVisible(state.fitting);
    if (state.fitting) {
        const int done = state.correctionsDone, allowed = state.correctionsAllowed;
        m_progress->setRange(0, std::max(allowed, 0)); // 0 … 0: busy, with no count
        m_progress->setValue(std::min(done, allowed));
        m_cancel->setEnabled(!state.cancelling && allowed > 0);
        if (state.cancelling)
            m_sseLabel->setText(
                QCoreApplication::translate("granota::ui::FitTab", "Cancelling: the fit stops after the correction under way…"));
        else if (allowed > 0)
            m_sseLabel->setText(
                QCoreApplication::translate("granota::ui::FitTab",
                                            "Fitting in the background: %1 of at most %2 parameter corrections made…")
                    .arg(done)
                    .arg(allowed));
        else
            m_sseLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "Fitting in the background…"));
        m_rmsLabel->clear();
        m_maxLabel->clear();
        m_condLabel->clear();
        m_correctionsLabel->hide();
    } else if (fit) {
        m_sseLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "Squared error Σ‖Qᵢ − α(tᵢ)‖²: %1")
                                .arg(fittedValueText(fit->sse)));
        m_rmsLabel->setText(
            QCoreApplication::translate("granota::ui::FitTab", "RMS error √(Σ/(k+1)): %1").arg(fittedValueText(fit->rms)));
        m_maxLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "Largest error max‖Qᵢ − α(tᵢ)‖: %1")
                                .arg(fittedValueText(fit->maxError)));
        m_condLabel->setText(
            fit->cond >= std::numeric_limits<double>::max()
                ? QCoreApplication::translate("granota::ui::FitTab", "Condition number cond₂(M): infinite (M is singular)")
                : QCoreApplication::translate("granota::ui::FitTab", "Condition number cond₂(M): %1")
                      .arg(fittedValueText(fit->cond)));
        m_correctionsLabel->setVisible(settings.correctParameters);
        m_correctionsLabel->setText(
            QCoreApplication::translate("granota::ui::FitTab", "Parameter corrections that lowered the error: %1")
                .arg(fit->corrections));
        if (fit->cancelled)
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "Cancelled after %1 of at most %2 parameter corrections: the curve shown is the best fit "
                            "found until then.")
                            .arg(fit->corrections)
                            .arg(settings.iterations);
    } else {
        m_sseLabel->setText(QCoreApplication::translate("granota::ui::FitTab", "No fit: %1").arg(state.fitError));
        m_rmsLabel->clear();
        m_maxLabel->clear();
        m_condLabel->clear();
        m_correctionsLabel->hide();
    }
    m_rmsLabel->setVisible(fit != nullptr);
    m_maxLabel->setVisible(fit != nullptr);
    m_condLabel->setVisible(fit != nullptr);
    warnings << warningLines(state);
    m_warningLabel->setText(warnings.join(QLatin1Char('\n')));
    m_warningLabel->setVisible(!warnings.isEmpty());
}

QStringList FitReadoutPanel::warningLines(const State& state) const
{
    // The core decides what to warn about (fit_warning.h); the panel only words it.
    FitOptions options;
    options.degree = state.fittedDegree;
    options.parametrization = state.settings->parametrization;
    options.solver = state.settings->solver;
    QStringList warnings;
    for (const FitWarning& w : fitWarnings(state.fit, *state.points, options)) {
        switch (w.code) {
        case FitWarningCode::IllConditioned:
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "⚠ Ill-conditioned: cond₂(M) ≈ %1. The control points are very sensitive to the data; "
                            "lower the degree.")
                            .arg(fittedValueText(w.cond));
            break;
        case FitWarningCode::HighDegree:
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "⚠ High degree n = %1: the Bernstein basis grows ill-conditioned (cond₂(M) ≈ %2); a "
                            "lower degree or a spline is usually the better model.")
                            .arg(w.degree)
                            .arg(fittedValueText(w.cond));
            break;
        case FitWarningCode::NormalEquationsSquare:
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "⚠ The normal equations square the condition number: cond₂(MᵀM) ≈ %1, so about %2 of "
                            "the 16 significant digits may be lost. Choose QR.")
                            .arg(fittedValueText(w.cond * w.cond))
                            .arg(normalEquationsDigitsLost(w.cond));
            break;
        case FitWarningCode::RepeatedParameters:
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "⚠ Only %1 distinct parameters tᵢ for %2 control points: M is rank deficient, and the "
                            "control points shown are the minimum-norm least-squares solution.")
                            .arg(w.distinct)
                            .arg(w.degree + 1);
            break;
        case FitWarningCode::AllCoincide:
            warnings << (w.byDistance ? QCoreApplication::translate(
                                            "granota::ui::FitTab",
                                            "All the data points coincide: the chord lengths are all zero, so uniform "
                                            "parameters are used instead.")
                                      : QCoreApplication::translate("granota::ui::FitTab",
                                                                    "All the data points coincide: the curve is that point."));
            break;
        case FitWarningCode::ZeroChords:
            warnings << QCoreApplication::translate(
                            "granota::ui::FitTab",
                            "Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such "
                            "pair(s)).",
                            nullptr, w.pairs)
                            .arg(w.first - 1)
                            .arg(w.first);
            break;
        case FitWarningCode::Collinear:
            warnings << QCoreApplication::translate(
                "granota::ui::FitTab",
                "The data points are collinear: the fitted curve and its control points lie on their line.");
            break;
        case FitWarningCode::CoincidentFallback:
        case FitWarningCode::CorrectionStopped:
        case FitWarningCode::RankDeficient: break; // fitBezier's notes for the CLI; fitWarnings() does not list them
        }
    }
    return warnings;
}

QString FitReadoutPanel::readoutText() const
{
    QStringList lines;
    for (const QLabel* label : {m_sseLabel, m_rmsLabel, m_maxLabel, m_condLabel})
        if (!label->text().isEmpty())
            lines << label->text();
    return lines.join(QLatin1Char('\n'));
}

QString FitReadoutPanel::warningText() const { return m_warningLabel->isVisibleTo(this) ? m_warningLabel->text() : QString(); }

QString FitReadoutPanel::headline() const { return m_sseLabel->text(); }

QString FitReadoutPanel::errorText(const Error& error, int degree, LeastSquaresSolver solver)
{
    switch (error.code) {
    case ErrorCode::TooFewPoints:
        return QCoreApplication::translate("granota::ui::FitTab", "A least-squares fit needs at least 2 data points.");
    case ErrorCode::DegreeTooHigh:
        return QCoreApplication::translate("granota::ui::FitTab", "Degree %1 needs at least %2 data points.")
            .arg(degree)
            .arg(degree + 1);
    case ErrorCode::Singular:
        return solver == LeastSquaresSolver::Normal
                   ? QCoreApplication::translate(
                         "granota::ui::FitTab",
                         "The normal equations MᵀM P = MᵀQ cannot be solved here: MᵀM is numerically singular "
                         "(coincident points, or cond₂(MᵀM) = cond₂(M)² beyond 10¹⁶). Choose QR or SVD.")
                   : QCoreApplication::translate("granota::ui::FitTab", "The least-squares system has no usable solution here.");
    case ErrorCode::OutOfRange:
        return QCoreApplication::translate("granota::ui::FitTab",
                                           "The fitted curve does not fit in double precision: lower the degree.");
    case ErrorCode::InvalidInput:
    default: return QCoreApplication::translate("granota::ui::FitTab", "A data point is not a finite number.");
    }
}

QString FitReadoutPanel::refusalText(int asked, int count)
{
    if (asked > kMaxFitDegree)
        return QCoreApplication::translate("granota::ui::FitTab",
                                           "Degree %1 is refused: the highest is %2, beyond which the Bernstein basis is too "
                                           "ill-conditioned for any solver.")
            .arg(asked)
            .arg(kMaxFitDegree);
    return QCoreApplication::translate("granota::ui::FitTab",
                                       "Degree %1 needs %2 data points (n + 1 ≤ k + 1); there are %3, so n ≤ %4.")
        .arg(asked)
        .arg(asked + 1)
        .arg(count)
        .arg(std::min(count - 1, kMaxFitDegree));
}

} // namespace granota::ui
