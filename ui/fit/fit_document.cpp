#include "ui/fit/fit_document.h"

#include "core/base/input_limits.h"
#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>
#include <QJsonValue>

#include <cmath>

namespace granota::ui {

void FitDocument::write(QJsonObject& state) const
{
    state.insert(QStringLiteral("degree"), settings.degree);
    state.insert(QStringLiteral("parametrization"), QString::fromStdString(toString(settings.parametrization)));
    state.insert(QStringLiteral("solver"), QString::fromStdString(toString(settings.solver)));
    state.insert(QStringLiteral("correctParameters"), settings.correctParameters);
    state.insert(QStringLiteral("iterations"), settings.iterations);
    state.insert(QStringLiteral("showMatrices"), showMatrices);
    state.insert(QStringLiteral("curvatureComb"), curvatureComb);
    state.insert(QStringLiteral("curvatureCombScale"), combScale);
    writeFitDisplay(display, state);
}

PointListMessages FitDocument::pointMessages()
{
    PointListMessages say;
    say.notAList = QCoreApplication::translate("granota::ui::FitTab", "The fitting tab's data points are missing or not a list.");
    say.badCount = [](int count) {
        return QCoreApplication::translate("granota::ui::FitTab",
                                           "The fitting tab holds %1 data points; Granota reads at most %2.")
            .arg(count)
            .arg(kMaxDataPoints);
    };
    say.notAPair = [](int i) {
        return QCoreApplication::translate("granota::ui::FitTab", "Data point Q%1 is not a pair of finite numbers.").arg(i);
    };
    say.tooFewAfterPoints = [] {
        return QCoreApplication::translate("granota::ui::FitTab", "The fitting tab needs at least 2 data points.");
    };
    return say;
}

std::optional<FitDocument> FitDocument::read(const QJsonObject& state, QString& error)
{
    FitDocument doc;
    FitSettings& s = doc.settings;
    const QJsonValue degree = state.value(QStringLiteral("degree"));
    if (!degree.isUndefined()) {
        const double d = degree.toDouble(-1);
        if (!degree.isDouble() || d != std::floor(d) || d < 0 || d > kMaxFitDegree) {
            error = QCoreApplication::translate("granota::ui::FitTab", "The degree must be a whole number from 0 to %1.")
                        .arg(kMaxFitDegree);
            return std::nullopt;
        }
        s.degree = static_cast<int>(d);
    }
    const QJsonValue param = state.value(QStringLiteral("parametrization"));
    if (!param.isUndefined()) {
        const auto p = parseParametrization(param.toString().toStdString());
        if (!p) {
            error = QCoreApplication::translate("granota::ui::FitTab", "Unknown parametrization “%1”.")
                        .arg(param.toVariant().toString());
            return std::nullopt;
        }
        s.parametrization = *p;
    }
    const QJsonValue solver = state.value(QStringLiteral("solver"));
    if (!solver.isUndefined()) {
        const auto p = parseLeastSquaresSolver(solver.toString().toStdString());
        if (!p) {
            error = QCoreApplication::translate("granota::ui::FitTab", "Unknown solver “%1”.").arg(solver.toVariant().toString());
            return std::nullopt;
        }
        s.solver = *p;
    }
    const QJsonValue correct = state.value(QStringLiteral("correctParameters"));
    if (!correct.isUndefined() && !correct.isBool()) {
        error = QCoreApplication::translate("granota::ui::FitTab", "“correctParameters” must be true or false.");
        return std::nullopt;
    }
    s.correctParameters = correct.toBool(false);
    const QJsonValue iterations = state.value(QStringLiteral("iterations"));
    if (!iterations.isUndefined()) {
        const double d = iterations.toDouble(-1);
        if (!iterations.isDouble() || d != std::floor(d) || d < 1 || d > FitSettings::kMaxIterations) {
            error = QCoreApplication::translate("granota::ui::FitTab",
                                                "The number of parameter corrections must be a whole number from 1 to %1.")
                        .arg(FitSettings::kMaxIterations);
            return std::nullopt;
        }
        s.iterations = static_cast<int>(d);
    }
    const QJsonValue matrices = state.value(QStringLiteral("showMatrices"));
    if (!matrices.isUndefined() && !matrices.isBool()) {
        error = QCoreApplication::translate("granota::ui::FitTab", "“showMatrices” must be true or false.");
        return std::nullopt;
    }
    doc.showMatrices = matrices.toBool(false);
    const QJsonValue comb = state.value(QStringLiteral("curvatureComb")); // older documents: off
    if (!comb.isUndefined() && !comb.isBool()) {
        error = QCoreApplication::translate("granota::ui::FitTab", "“curvatureComb” must be true or false.");
        return std::nullopt;
    }
    doc.curvatureComb = comb.toBool(false);
    QString badKey;
    const std::optional<FitDisplay> display = readFitDisplay(state, &badKey); // older documents: as before the keys
    if (!display) {
        error = badKey == QLatin1String("samples")
                    ? QCoreApplication::translate("granota::ui::FitTab", "“samples” must be a whole number from %1 to %2.")
                          .arg(FitDisplay::kMinSamples)
                          .arg(FitDisplay::kMaxSamples)
                    : QCoreApplication::translate("granota::ui::FitTab", "“%1” must be true or false.").arg(badKey);
        return std::nullopt;
    }
    doc.display = *display;
    const QJsonValue combScale = state.value(QStringLiteral("curvatureCombScale")); // older documents: automatic
    if (!combScale.isUndefined() && (!combScale.isDouble() || !std::isfinite(combScale.toDouble()) || combScale.toDouble() < 0 ||
                                     combScale.toDouble() > CurvatureCombScaleBox::kMaxScale)) {
        error = QCoreApplication::translate("granota::ui::FitTab",
                                            "“curvatureCombScale” must be 0 (automatic) or a positive number up to %1.")
                    .arg(displayNumber(CurvatureCombScaleBox::kMaxScale));
        return std::nullopt;
    }
    doc.combScale = combScale.toDouble(0.0);
    return doc;
}

} // namespace granota::ui
