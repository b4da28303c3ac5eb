#pragma once
/// \file expected.h
/// Errors a user can cause are values, not crashes: a function that can fail on user
/// input returns Expected<T>, holding either the result or an Error with a message.
/// (C++17 has no std::expected; this is the small part of it Granota needs.)
/// Expected<void> is a check or an action that has no result: success is `return {};`.

#include "core/base/message_id.h"

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace granota {

/// What went wrong, in words a user can act on. `code` lets the GUI pick a translated text.
enum class ErrorCode {
    InvalidInput,  ///< malformed text, NaN/inf, wrong shape
    TooFewPoints,  ///< not enough points for the construction
    DegreeTooHigh, ///< degree not supported by the number of (distinct) points
    NotRational,   ///< an exact computation was asked for non-rational data
    Singular,      ///< a linear system has no unique solution
    NotIncreasing, ///< abscissae of a function spline must increase strictly
    OutOfRange,    ///< a parameter outside its meaningful range
    Cancelled,     ///< the user stopped a long computation
    NotAFile,      ///< a path names a folder, a pipe or a device where a file was wanted
    SystemRefused, ///< the system refused to read or write a file: Error::systemError says why
    CutOff,        ///< a text ends before its value does (a file cut short): the message says where
};

struct Error {
    ErrorCode code = ErrorCode::InvalidInput;
    std::string message;            ///< English, as the CLI prints it
    int systemError = 0;            ///< the errno of a refused read or write (ENOSPC, EROFS, EACCES…), else 0
    MessageId id = MessageId::None; ///< the sentence, for the GUI's translation (message_id.h)
    std::vector<MessageArg> args;   ///< the values the sentence quotes, in order
    long line = 0;                  ///< the line of a text file the error is on, else 0
};

template <class T> class Expected {
public:
    Expected(T value) : m_v(std::move(value)) {}
    Expected(Error error) : m_v(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(m_v); }
    explicit operator bool() const { return ok(); }

    const T& value() const&
    {
        assert(ok());
        return std::get<T>(m_v);
    }
    T& value() &
    {
        assert(ok());
        return std::get<T>(m_v);
    }
    T&& value() &&
    {
        assert(ok());
        return std::get<T>(std::move(m_v));
    }
    const T& operator*() const& { return value(); }
    T& operator*() & { return value(); }
    const T* operator->() const { return &value(); }
    T* operator->() { return &value(); }

    const Error& error() const
    {
        assert(!ok());
        return std::get<Error>(m_v);
    }

private:
    std::variant<T, Error> m_v;
};

/// A check or an action that yields nothing but may fail: `return {};` on success, an Error
/// otherwise. Tested as the general one (ok(), operator bool, error()).
template <> class Expected<void> {
public:
    Expected() = default;
    Expected(Error error) : m_error(std::move(error)) {}

    bool ok() const { return !m_error.has_value(); }
    explicit operator bool() const { return ok(); }

    void value() const { assert(ok()); }

    const Error& error() const
    {
        assert(!ok());
        return *m_error;
    }

private:
    std::optional<Error> m_error;
};

inline Error makeError(ErrorCode code, std::string message) { return Error{code, std::move(message), 0, MessageId::None, {}, 0}; }

/// An Error that the GUI translates: `message` in English for the CLI, `id` and `args` for
/// the GUI's own words (ui/common/error_text.cpp).
inline Error makeError(ErrorCode code, std::string message, MessageId id, std::vector<MessageArg> args)
{
    return Error{code, std::move(message), 0, id, std::move(args), 0};
}

/// `error` with `context` before its English ("scene 'x': …", "line 3: …"); the sentence the
/// GUI translates, its arguments and its line stay.
inline Error withContext(std::string context, Error error)
{
    error.message = std::move(context) + error.message;
    return error;
}

} // namespace granota
