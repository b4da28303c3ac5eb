#pragma once
/// \file arguments.h
/// Command-line arguments of granota-cli: `granota-cli COMMAND [--option value]… [--flag]…`.
/// Each command declares its options; anything undeclared is an error (exit 2), so a typo
/// never silently falls back to a default.

#include "core/base/expected.h"
#include "core/exact/rational.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace granota::cli {

struct CommandSyntax {
    std::set<std::string> valueOptions; ///< options followed by a value, e.g. "points"
    std::set<std::string> flags;        ///< options without a value, e.g. "exact"
    std::set<std::string> repeatable;   ///< value options that may be given several times
    std::size_t maxPositional = 0;      ///< plain words allowed before/among the options (report NAME)
};

class Arguments {
public:
    static Expected<Arguments> parse(const std::vector<std::string>& args, const CommandSyntax& syntax);

    bool has(const std::string& name) const { return m_values.count(name) || m_flags.count(name); }
    bool flag(const std::string& name) const { return m_flags.count(name) != 0; }
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    /// The plain words (not options), in order; at most CommandSyntax::maxPositional.
    const std::vector<std::string>& positional() const { return m_positional; }

    /// A rational option (integers, decimals, fractions), or `fallback` when absent.
    Expected<Rational> rational(const std::string& name, std::optional<Rational> fallback) const;
    /// A comma-separated list of rationals ("1,1/2,0.25"), as many as written; an error names
    /// the first entry that is not a number. Empty when the option is absent.
    Expected<std::vector<Rational>> rationalList(const std::string& name) const;
    /// An integer option within [min, max], or `fallback` when absent.
    Expected<int> integer(const std::string& name, int min, int max, std::optional<int> fallback) const;
    /// One of `choices`, or `fallback` when absent.
    Expected<std::string> choice(const std::string& name, const std::vector<std::string>& choices,
                                 std::optional<std::string> fallback) const;
    /// Points from --points "x,y;…" or --points-file F (CSV or JSON), exactly one of them.
    Expected<std::vector<RPoint>> points() const;

private:
    std::map<std::string, std::vector<std::string>> m_values;
    std::set<std::string> m_flags;
    std::vector<std::string> m_positional;
};

} // namespace granota::cli
