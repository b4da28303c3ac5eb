#pragma once
/// \file fit_readout_panel.h
/// The Fitting tab's "Quality of the fit" group (Prop 2.2): the readouts (the squared error,
/// RMS, largest error, cond₂(M), the corrections made), the warnings worded from the core's
/// (core/curves/fitting/fit_warning.h), and, while a fit runs in the background
/// (background_fit.h), its progress and Cancel. Also the words for why there is no fit or why
/// a degree is refused. It only words: every value comes from the core.
/// Its texts keep the tab's translation context (granota::ui::FitTab), so the translations still match.

#include "core/base/expected.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "ui/fit/fit_settings.h"

#include <QGroupBox>
#include <QString>

#include <vector>

class QLabel;
class QProgressBar;
class QPushButton;

namespace granota::ui {

/// A fitted value in a label: six significant digits.
QString fittedValueText(double v);

class FitReadoutPanel : public QGroupBox {
public:
    explicit FitReadoutPanel(QWidget* parent);

    /// What the panel shows.
    struct State {
        const std::vector<Point>* points = nullptr; ///< Q_0…Q_k
        const FitResult* fit = nullptr;             ///< nullptr: no fit (fitError says why) or fitting
        QString fitError;
        QString refusal; ///< the last refused degree's reason, shown until the next fit
        const FitSettings* settings = nullptr;
        int fittedDegree = 0;
        bool fitting = false; ///< a fit runs in the background
        bool cancelling = false;
        int correctionsDone = 0, correctionsAllowed = 0;
    };
    void showState(const State& state);
    void retranslate();

    /// The readouts (error, RMS, max, cond₂) and the warnings as shown.
    QString readoutText() const;
    QString warningText() const;
    /// The first readout: the squared error, or what the background fit is doing.
    QString headline() const;
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }

    /// Why there is no fit, for `degree` fitted with `solver`.
    static QString errorText(const Error& error, int degree, LeastSquaresSolver solver);
    /// Why the degree `asked` is refused with `count` data points (more than k, or more than kMaxFitDegree).
    static QString refusalText(int asked, int count);

private:
    QStringList warningLines(const State& state) const;

    QLabel* m_sseLabel = nullptr;
    QLabel* m_rmsLabel = nullptr;
    QLabel* m_maxLabel = nullptr;
    QLabel* m_condLabel = nullptr;
    QLabel* m_correctionsLabel = nullptr;
    QLabel* m_warningLabel = nullptr;
    QProgressBar* m_progress = nullptr; ///< corrections made by a fit in the background
    QPushButton* m_cancel = nullptr;    ///< stops it
};

} // namespace granota::ui
