#include "ui/catmull_rom/plane_spline_settings.h"

#include <QStringList>

namespace granota::ui {

namespace {

QString planeSplineNameText(std::string_view name) { return QString::fromUtf8(name.data(), static_cast<int>(name.size())); }

} // namespace

bool PlaneSplineSettings::operator==(const PlaneSplineSettings& o) const
{
    return ends == o.ends && parameters == o.parameters && startTangent.x == o.startTangent.x &&
           startTangent.y == o.startTangent.y && endTangent.x == o.endTangent.x && endTangent.y == o.endTangent.y &&
           catmullRomToo == o.catmullRomToo;
}

std::optional<RPoint> parseTangent(const QString& text)
{
    QString t = text.trimmed();
    t.replace(QChar(0x2212), QLatin1Char('-')); // "−1/2" as the thesis prints it
    t.remove(QLatin1Char(' '));
    const QStringList parts = t.split(QLatin1Char(','));
    if (parts.size() != 2)
        return std::nullopt;
    RPoint out;
    for (int i = 0; i < 2; ++i) {
        const auto value = parseRational(parts[i].toStdString());
        if (!value || abs(*value) > PlaneSplineSettings::kMaxTangentAbs)
            return std::nullopt;
        (i == 0 ? out.x : out.y) = *value;
    }
    return out;
}

QString tangentText(const RPoint& tangent)
{
    return QString::fromStdString(toString(tangent.x)) + QStringLiteral(", ") + QString::fromStdString(toString(tangent.y));
}

void writePlaneSplineSettings(const PlaneSplineSettings& s, QJsonObject& json)
{
    json.insert(QStringLiteral("ends"), planeSplineNameText(parametricEndsName(s.ends)));
    json.insert(QStringLiteral("parameters"), planeSplineNameText(splineParametersName(s.parameters)));
    json.insert(QStringLiteral("start_tangent"), tangentText(s.startTangent));
    json.insert(QStringLiteral("end_tangent"), tangentText(s.endTangent));
    json.insert(QStringLiteral("catmull_rom_too"), s.catmullRomToo);
}

std::optional<PlaneSplineSettings> readPlaneSplineSettings(const QJsonObject& json, QString* problem)
{
    auto fail = [problem](const QString& why) -> std::optional<PlaneSplineSettings> {
        if (problem)
            *problem = why;
        return std::nullopt;
    };
    PlaneSplineSettings s;
    const QJsonValue ends = json.value(QStringLiteral("ends"));
    if (!ends.isUndefined()) {
        const auto e = ends.isString() ? parseParametricEnds(ends.toString().toStdString()) : std::nullopt;
        if (!e)
            return fail(QStringLiteral("ends"));
        s.ends = *e;
    }
    const QJsonValue parameters = json.value(QStringLiteral("parameters"));
    if (!parameters.isUndefined()) {
        const auto p = parameters.isString() ? parseSplineParameters(parameters.toString().toStdString()) : std::nullopt;
        if (!p)
            return fail(QStringLiteral("parameters"));
        s.parameters = *p;
    }
    for (const auto& [key, target] : {std::pair{"start_tangent", &s.startTangent}, std::pair{"end_tangent", &s.endTangent}}) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        const std::optional<RPoint> tangent = v.isString() ? parseTangent(v.toString()) : std::nullopt;
        if (!tangent)
            return fail(QLatin1String(key));
        *target = *tangent;
    }
    const QJsonValue too = json.value(QStringLiteral("catmull_rom_too"));
    if (!too.isUndefined()) {
        if (!too.isBool())
            return fail(QStringLiteral("catmull_rom_too"));
        s.catmullRomToo = too.toBool();
    }
    return s;
}

} // namespace granota::ui
