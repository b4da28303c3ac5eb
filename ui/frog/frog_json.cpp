#include "ui/frog/frog_json.h"

#include <QJsonArray>
#include <QJsonObject>

namespace granota::ui {

QJsonValue toQJson(const Json& v)
{
    if (auto b = v.asBool())
        return *b;
    if (auto d = v.asNumber())
        return *d;
    if (auto s = v.asString())
        return QString::fromStdString(*s);
    if (const auto* a = v.asArray()) {
        QJsonArray out;
        for (const Json& item : *a)
            out.append(toQJson(item));
        return out;
    }
    if (const auto* o = v.asObject()) {
        QJsonObject out;
        for (const auto& [key, item] : *o)
            out.insert(QString::fromStdString(key), toQJson(item));
        return out;
    }
    return QJsonValue::Null;
}

Json fromQJson(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Bool: return Json(v.toBool());
    case QJsonValue::Double: return Json(v.toDouble());
    case QJsonValue::String: return Json(v.toString().toStdString());
    case QJsonValue::Array: {
        Json out = Json::array();
        for (const QJsonValue& item : v.toArray())
            out.push(fromQJson(item));
        return out;
    }
    case QJsonValue::Object: {
        Json out = Json::object();
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            out.set(it.key().toStdString(), fromQJson(it.value()));
        return out;
    }
    default: return Json();
    }
}

} // namespace granota::ui
