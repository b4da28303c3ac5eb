#include "ui/decasteljau/decasteljau_view.h"

#include "ui/common/curvature_comb_scale_box.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>
#include <QJsonValue>

#include <algorithm>
#include <cmath>
#include <utility>

namespace granota::ui {

namespace {

/// The display options that are true or false, with their keys: one table for reading and writing.
const std::pair<const char*, bool DeCasteljauView::*> kViewFlags[] = {
    {"control_points", &DeCasteljauView::controlPoints},
    {"construction", &DeCasteljauView::construction},
    {"stepByStep", &DeCasteljauView::stepByStep},
    {"tangent", &DeCasteljauView::tangent},
    {"split", &DeCasteljauView::split},
    {"snap", &DeCasteljauView::snap},
    {"normal", &DeCasteljauView::normal},
    {"osculatingCircle", &DeCasteljauView::osculatingCircle},
    {"curvatureComb", &DeCasteljauView::comb},
    {"boundingBox", &DeCasteljauView::boundingBox},
    {"inflections", &DeCasteljauView::inflections},
    {"hodograph", &DeCasteljauView::hodograph},
    {"constantSpeed", &DeCasteljauView::constantSpeed},
};

} // namespace

DeCasteljauView DeCasteljauView::clamped() const
{
    DeCasteljauView v = *this;
    v.samples = std::clamp(samples, kMinSamples, kMaxSamples);
    v.combScale = std::isfinite(combScale) ? std::clamp(combScale, 0.0, CurvatureCombScaleBox::kMaxScale) : 0.0;
    return v;
}

bool operator==(const DeCasteljauView& a, const DeCasteljauView& b)
{
    for (const auto& flag : kViewFlags)
        if (a.*flag.second != b.*flag.second)
            return false;
    return a.samples == b.samples && a.combScale == b.combScale;
}

void writeDeCasteljauView(const DeCasteljauView& view, QJsonObject& json)
{
    json.insert(QStringLiteral("samples"), view.samples);
    for (const auto& [key, member] : kViewFlags)
        json.insert(QLatin1String(key), view.*member);
    json.insert(QStringLiteral("curvatureCombScale"), view.combScale);
}

std::optional<DeCasteljauView> readDeCasteljauView(const QJsonObject& json, QString& error)
{
    DeCasteljauView view; // older documents: what they lack has its default (the overlays off)
    if (const QJsonValue v = json.value(QStringLiteral("samples")); !v.isUndefined()) {
        const double s = v.toDouble(-1);
        if (!v.isDouble() || s != std::floor(s) || s < DeCasteljauView::kMinSamples || s > DeCasteljauView::kMaxSamples) {
            error = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                "The number of samples must be a whole number from %1 to %2.")
                        .arg(DeCasteljauView::kMinSamples)
                        .arg(DeCasteljauView::kMaxSamples);
            return std::nullopt;
        }
        view.samples = static_cast<int>(s);
    }
    for (const auto& [key, member] : kViewFlags) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        if (!v.isBool()) {
            error = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                "A De Casteljau display option is not true or false.");
            return std::nullopt;
        }
        view.*member = v.toBool();
    }
    if (const QJsonValue v = json.value(QStringLiteral("curvatureCombScale")); !v.isUndefined()) {
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < 0 ||
            v.toDouble() > CurvatureCombScaleBox::kMaxScale) {
            error = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                "The comb's scale must be 0 (automatic) or a positive number up to %1.")
                        .arg(displayNumber(CurvatureCombScaleBox::kMaxScale));
            return std::nullopt;
        }
        view.combScale = v.toDouble();
    }
    return view;
}

} // namespace granota::ui
