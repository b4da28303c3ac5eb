#include "ui/catmull_rom/function_data_settings.h"

namespace granota::ui {

QString functionDataCurveKey(FunctionDataCurve curve)
{
    switch (curve) {
    case FunctionDataCurve::Natural: return QStringLiteral("natural");
    case FunctionDataCurve::CatmullRom: return QStringLiteral("catmull_rom");
    case FunctionDataCurve::FritschCarlson: return QStringLiteral("fritsch_carlson");
    case FunctionDataCurve::Steffen: return QStringLiteral("steffen");
    }
    return {};
}

void writeFunctionDataSettings(const FunctionDataSettings& s, QJsonObject& json)
{
    for (FunctionDataCurve curve : kFunctionDataCurves)
        json.insert(functionDataCurveKey(curve), s.isShown(curve));
    json.insert(QStringLiteral("shade_overshoot"), s.shadeOvershoot);
}

std::optional<FunctionDataSettings> readFunctionDataSettings(const QJsonObject& json, QString* problem)
{
    FunctionDataSettings s;
    auto readFlag = [&json, problem](const QString& key, bool& target) {
        const QJsonValue v = json.value(key);
        if (v.isUndefined())
            return true;
        if (!v.isBool()) {
            if (problem)
                *problem = key;
            return false;
        }
        target = v.toBool();
        return true;
    };
    for (FunctionDataCurve curve : kFunctionDataCurves)
        if (!readFlag(functionDataCurveKey(curve), s.shown[static_cast<std::size_t>(curve)]))
            return std::nullopt;
    if (!readFlag(QStringLiteral("shade_overshoot"), s.shadeOvershoot))
        return std::nullopt;
    return s;
}

} // namespace granota::ui
