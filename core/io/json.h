#pragma once
/// \file json.h
/// A small JSON value for Granota's data files (scenes, examples, point lists) and the
/// CLI's output. Objects keep their keys in the order they were read or set, so what is
/// written reads in a fixed order. Numbers are doubles, written in their shortest
/// round-trip form and read the same in any locale; a number read by parse() also keeps
/// its text as written, for readers that need it exactly (0.1 as 1/10, not a double).
/// parse() takes strict JSON only (nlohmann-json does the reading, out of sight of this
/// header): anything else, nesting deeper than kMaxDepth, or a number too large for a
/// double, is an Error naming the line and column (from 1, in bytes) where it stops.

#include "core/base/expected.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace granota {

class Json {
public:
    using Array = std::vector<Json>;
    using Object = std::vector<std::pair<std::string, Json>>;

    /// Deepest nesting of arrays and objects parse() accepts.
    static constexpr int kMaxDepth = 256;

    Json() : m_v(nullptr) {}
    Json(bool b) : m_v(b) {}
    Json(double d) : m_v(Number{d, {}}) {}
    Json(int i) : m_v(Number{static_cast<double>(i), {}}) {}
    Json(const char* s) : m_v(std::string(s)) {}
    Json(std::string s) : m_v(std::move(s)) {}
    Json(Array a) : m_v(std::move(a)) {}
    Json(Object o) : m_v(std::move(o)) {}

    static Json array() { return Json(Array{}); }
    static Json object() { return Json(Object{}); }
    static Expected<Json> parse(std::string_view text);

    /// Where parse() hands over the elements of one array instead of keeping them: the
    /// array that is the member `key` of the top-level object. Each element is passed whole,
    /// in order, with its index (0 again if the key is repeated: the last array is the
    /// one that counts); the member itself is left an empty array. A file of millions of
    /// small rows (a recording's events) is then never held as a tree of Json values,
    /// some 200 bytes a row, beside what the reader makes of it.
    struct ElementSink {
        std::string key;
        std::function<void(std::size_t index, Json&& element)> take;
    };
    /// parse(), with the elements of `sink.key` streamed to `sink.take`.
    static Expected<Json> parse(std::string_view text, const ElementSink& sink);

    bool isNull() const { return std::holds_alternative<std::nullptr_t>(m_v); }
    bool isBool() const { return std::holds_alternative<bool>(m_v); }
    bool isNumber() const { return std::holds_alternative<Number>(m_v); }
    bool isString() const { return std::holds_alternative<std::string>(m_v); }
    bool isArray() const { return std::holds_alternative<Array>(m_v); }
    bool isObject() const { return std::holds_alternative<Object>(m_v); }

    /// The value, or nullopt when it has another type.
    std::optional<bool> asBool() const;
    std::optional<double> asNumber() const;
    /// A parsed number's text as written ("0.10", "-0", "1e2"); nullopt if made in code.
    std::optional<std::string_view> numberText() const;
    std::optional<std::string> asString() const;
    const Array* asArray() const { return std::get_if<Array>(&m_v); }
    const Object* asObject() const { return std::get_if<Object>(&m_v); }
    /// The member `key` of an object; nullptr when absent or not an object.
    const Json* find(const std::string& key) const;

    /// Appends to an array.
    Json& push(Json v);
    /// Sets a key of an object (replacing it if present, else appended in order).
    Json& set(const std::string& key, Json v);

    /// Compact text; `indent` > 0 pretty-prints with that many spaces.
    std::string dump(int indent = 0) const;

private:
    /// A number with, when parse() read it, its text (empty for numbers made in code).
    struct Number {
        double value;
        std::string text;
    };
    struct Reader; ///< parse()'s handler of nlohmann's events (json.cpp)

    void write(std::string& out, int indent, int depth) const;
    std::variant<std::nullptr_t, bool, Number, std::string, Array, Object> m_v;
};

} // namespace granota
