#pragma once
/// \file error_text.h
/// A core Error in the interface's language. The core writes English for the CLI and names
/// the sentence with a MessageId and its values (core/base/message_id.h); this says that
/// sentence in the language in use, with numbers in its decimal sign and a scene parameter
/// by its label on the Frog tab's panel rather than its key. An Error without a sentence
/// is worded by its kind (ErrorCode) — or, in English, shown as the core wrote it.

#include "core/base/expected.h"

#include <QCoreApplication>
#include <QString>

namespace granota::ui {

class ErrorText {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::ErrorText)

public:
    /// The whole sentence, with the CSV line when the error has one ("Line 3: …").
    static QString of(const Error& error);
    /// A scene parameter's key ("area_factor") as the panel labels it ("Area factor").
    static QString parameterLabel(const std::string& key);
};

} // namespace granota::ui
