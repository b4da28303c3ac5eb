#include "ui/files/tikz_options.h"

#include <QSettings>
#include <QString>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

double sizeFrom(const QSettings& settings, const QString& key, double fallback)
{
    bool ok = false;
    const double v = settings.value(key, fallback).toDouble(&ok);
    return ok && std::isfinite(v) ? std::clamp(v, TikzOptions::kMinCm, TikzOptions::kMaxCm) : fallback;
}

} // namespace

TikzOptions TikzOptions::load()
{
    const QSettings settings;
    TikzOptions o;
    o.widthCm = sizeFrom(settings, QStringLiteral("tikz/widthCm"), kDefaultWidthCm);
    o.maxHeightCm = sizeFrom(settings, QStringLiteral("tikz/maxHeightCm"), kDefaultMaxHeightCm);
    o.axes = settings.value(QStringLiteral("tikz/axes"), false).toBool();
    o.grid = settings.value(QStringLiteral("tikz/grid"), false).toBool();
    return o;
}

void TikzOptions::save() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("tikz/widthCm"), widthCm);
    settings.setValue(QStringLiteral("tikz/maxHeightCm"), maxHeightCm);
    settings.setValue(QStringLiteral("tikz/axes"), axes);
    settings.setValue(QStringLiteral("tikz/grid"), grid);
}

} // namespace granota::ui
