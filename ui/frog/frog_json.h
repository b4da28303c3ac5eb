#pragma once
/// \file frog_json.h
/// The core's Json (scene files) and Qt's QJsonValue (the .granota document), both ways.

#include "core/io/json.h"

#include <QJsonValue>

namespace granota::ui {

QJsonValue toQJson(const Json& value);
Json fromQJson(const QJsonValue& value);

} // namespace granota::ui
