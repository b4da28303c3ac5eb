#pragma once
/// \file frog_json.h
/// The core's Json (scene files) and Qt's QJsonValue (the .granota document), both ways.

#include "core/io/json.h"
#include "core/softbody/recorded_run.h"

#include <QJsonValue>

namespace granota::ui {

QJsonValue toQJson(const Json& value);
Json fromQJson(const QJsonValue& value);

/// A document's "recording" (documentRunFromJson's checks and messages), read an event at a
/// time: a run of millions of events is never a Json tree beside the document's own.
Expected<DocumentRun> documentRunFromQJson(const QJsonValue& value);
/// documentRunToJson(run) as Qt's JSON, made an event at a time likewise.
QJsonValue documentRunToQJson(const RecordedRun& run);

} // namespace granota::ui
