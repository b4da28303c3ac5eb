#include "ui/bsplines/bspline_model.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace granota::ui {

bool BSplineModel::operator==(const BSplineModel& o) const
{
    return degree == o.degree && preset == o.preset && knots == o.knots && weights == o.weights && u == o.u && net == o.net &&
           bezierSegments == o.bezierSegments && cubicCircle == o.cubicCircle && curvaturePlot == o.curvaturePlot &&
           homogeneousCurve == o.homogeneousCurve;
}

int BSplineModel::degreeFor(int pointCount) const { return std::clamp(std::min(degree, pointCount - 1), 1, kMaxBSplineDegree); }

std::vector<Rational> BSplineModel::knotsFor(int pointCount) const
{
    const int p = degreeFor(pointCount);
    if (static_cast<int>(knots.size()) == pointCount + p + 1)
        return knots;
    std::vector<Rational> made = presetKnots<Rational>(preset, pointCount, p);
    if (made.empty())
        made = presetKnots<Rational>(KnotPreset::Clamped, pointCount, p);
    return made;
}

std::vector<Rational> BSplineModel::weightsFor(int pointCount) const
{
    return static_cast<int>(weights.size()) == pointCount ? weights : std::vector<Rational>();
}

Rational BSplineModel::uFor(int pointCount) const
{
    const std::vector<Rational> k = knotsFor(pointCount);
    const int p = degreeFor(pointCount);
    if (static_cast<int>(k.size()) < pointCount + p + 1 || pointCount < 2)
        return u;
    const Rational& lo = k[static_cast<std::size_t>(p)];
    const Rational& hi = k[static_cast<std::size_t>(pointCount)];
    return u < lo ? lo : (hi < u ? hi : u);
}

QString presetKey(KnotPreset preset)
{
    switch (preset) {
    case KnotPreset::Clamped: return QStringLiteral("clamped");
    case KnotPreset::Uniform: return QStringLiteral("uniform");
    case KnotPreset::Bezier: return QStringLiteral("bezier");
    }
    return {};
}

std::optional<KnotPreset> presetFromKey(const QString& key)
{
    for (KnotPreset k : {KnotPreset::Clamped, KnotPreset::Uniform, KnotPreset::Bezier})
        if (presetKey(k) == key)
            return k;
    return std::nullopt;
}

namespace {

QJsonArray rationalArray(const std::vector<Rational>& values)
{
    QJsonArray a;
    for (const Rational& v : values)
        a.append(QString::fromStdString(toString(v)));
    return a;
}

/// A list of exact numbers, each a string ("1/3") or a JSON number.
std::optional<std::vector<Rational>> readRationals(const QJsonValue& value)
{
    if (!value.isArray())
        return std::nullopt;
    std::vector<Rational> out;
    for (const QJsonValue& v : value.toArray()) {
        std::optional<Rational> q;
        if (v.isString())
            q = parseRational(v.toString().toStdString());
        else if (v.isDouble() && std::isfinite(v.toDouble()))
            q = exactRational(v.toDouble());
        if (!q)
            return std::nullopt;
        out.push_back(*q);
    }
    return out;
}

std::optional<Rational> readRational(const QJsonValue& v)
{
    if (v.isString())
        return parseRational(v.toString().toStdString());
    if (v.isDouble() && std::isfinite(v.toDouble()))
        return exactRational(v.toDouble());
    return std::nullopt;
}

} // namespace

void writeModel(const BSplineModel& m, QJsonObject& json)
{
    json.insert(QStringLiteral("degree"), m.degree);
    json.insert(QStringLiteral("knot_preset"), presetKey(m.preset));
    if (!m.knots.empty())
        json.insert(QStringLiteral("knots"), rationalArray(m.knots));
    if (!m.weights.empty())
        json.insert(QStringLiteral("weights"), rationalArray(m.weights));
    json.insert(QStringLiteral("u"), QString::fromStdString(toString(m.u)));
    json.insert(QStringLiteral("net"), m.net);
    json.insert(QStringLiteral("bezier_segments"), m.bezierSegments);
    if (m.cubicCircle)
        json.insert(QStringLiteral("cubic_circle"), true);
    if (m.curvaturePlot)
        json.insert(QStringLiteral("curvature_plot"), true);
    if (m.homogeneousCurve)
        json.insert(QStringLiteral("homogeneous_curve"), true);
}

std::optional<BSplineModel> readModel(const QJsonObject& json, QString* problem)
{
    BSplineModel m;
    const auto fail = [problem](const char* key) -> std::optional<BSplineModel> {
        if (problem)
            *problem = QString::fromLatin1(key);
        return std::nullopt;
    };
    if (const QJsonValue v = json.value(QStringLiteral("degree")); !v.isUndefined()) {
        if (!v.isDouble() || v.toDouble() != static_cast<int>(v.toDouble()) || v.toInt() < 1 || v.toInt() > kMaxBSplineDegree)
            return fail("degree");
        m.degree = v.toInt();
    }
    if (const QJsonValue v = json.value(QStringLiteral("knot_preset")); !v.isUndefined()) {
        const auto preset = presetFromKey(v.toString());
        if (!preset)
            return fail("knot_preset");
        m.preset = *preset;
    }
    if (const QJsonValue v = json.value(QStringLiteral("knots")); !v.isUndefined()) {
        const auto knots = readRationals(v);
        if (!knots)
            return fail("knots");
        m.knots = *knots;
    }
    if (const QJsonValue v = json.value(QStringLiteral("weights")); !v.isUndefined()) {
        const auto weights = readRationals(v);
        if (!weights)
            return fail("weights");
        m.weights = *weights;
    }
    if (const QJsonValue v = json.value(QStringLiteral("u")); !v.isUndefined()) {
        const auto u = readRational(v);
        if (!u)
            return fail("u");
        m.u = *u;
    }
    const std::pair<const char*, bool BSplineModel::*> flags[] = {{"net", &BSplineModel::net},
                                                                  {"bezier_segments", &BSplineModel::bezierSegments},
                                                                  {"cubic_circle", &BSplineModel::cubicCircle},
                                                                  {"curvature_plot", &BSplineModel::curvaturePlot},
                                                                  {"homogeneous_curve", &BSplineModel::homogeneousCurve}};
    for (const auto& [key, flag] : flags) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        if (!v.isBool())
            return fail(key);
        m.*flag = v.toBool();
    }
    return m;
}

} // namespace granota::ui
