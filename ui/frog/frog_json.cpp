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

Expected<DocumentRun> documentRunFromQJson(const QJsonValue& value)
{
    if (!value.isObject())
        return documentRunFromJson(fromQJson(value)); // refused: not an object
    const QJsonObject o = value.toObject();
    // Everything but the events, checked by the core with no events yet.
    Json head = Json::object();
    for (auto it = o.begin(); it != o.end(); ++it)
        if (it.key() != QLatin1String("events"))
            head.set(it.key().toStdString(), fromQJson(it.value()));
    const QJsonValue events = o.value(QStringLiteral("events"));
    if (!events.isArray()) {
        if (!events.isUndefined())
            head.set("events", fromQJson(events));
        return documentRunFromJson(head); // refused: "events" is no array
    }
    head.set("events", Json::array());
    auto run = documentRunFromJson(head);
    if (!run)
        return run.error();
    const QJsonArray rows = events.toArray();
    EventListReader reader(run->steps);
    reader.reserve(static_cast<std::size_t>(rows.size()));
    for (const QJsonValue& row : rows)
        reader.add(fromQJson(row));
    auto list = std::move(reader).finish(run->steps);
    if (!list)
        return list.error();
    run->events = std::move(list).value();
    return run;
}

QJsonValue documentRunToQJson(const RecordedRun& run)
{
    QJsonArray events;
    for (const InputEvent& e : run.recording().events)
        events.append(toQJson(eventToJson(e)));
    QJsonObject doc;
    doc.insert(QStringLiteral("steps"), static_cast<double>(run.recordedSteps()));
    doc.insert(QStringLiteral("step"), static_cast<double>(run.stepCount()));
    doc.insert(QStringLiteral("events"), events);
    return doc;
}

} // namespace granota::ui
