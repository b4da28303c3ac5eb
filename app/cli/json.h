#pragma once
/// \file json.h
/// A tiny JSON value that keeps the order of object keys as the SPEC §6 contract lists
/// them, and writes doubles in their shortest round-trip form.

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace granota::cli {

class Json {
public:
    using Array = std::vector<Json>;
    using Object = std::vector<std::pair<std::string, Json>>;

    Json() : m_v(nullptr) {}
    Json(bool b) : m_v(b) {}
    Json(double d) : m_v(d) {}
    Json(int i) : m_v(static_cast<double>(i)) {}
    Json(const char* s) : m_v(std::string(s)) {}
    Json(std::string s) : m_v(std::move(s)) {}
    Json(Array a) : m_v(std::move(a)) {}
    Json(Object o) : m_v(std::move(o)) {}

    static Json array() { return Json(Array{}); }
    static Json object() { return Json(Object{}); }

    /// Appends to an array.
    Json& push(Json v);
    /// Sets a key of an object (appended in order of insertion).
    Json& set(const std::string& key, Json v);

    std::string dump() const;

private:
    void write(std::string& out) const;
    std::variant<std::nullptr_t, bool, double, std::string, Array, Object> m_v;
};

} // namespace granota::cli
