#include "app/cli/arguments.h"

#include "core/base/bounded_file.h"
#include "core/base/display_text.h"
#include "core/base/input_limits.h"
#include "core/base/text.h"
#include "core/io/point_list.h"

namespace granota::cli {

namespace {

/// An option that was not given: its fallback, or the error that it is required.
template <class T> Expected<T> absent(const std::string& name, const std::optional<T>& fallback)
{
    if (fallback)
        return *fallback;
    return makeError(ErrorCode::InvalidInput, "--" + name + " is required");
}

} // namespace

Expected<Arguments> Arguments::parse(const std::vector<std::string>& args, const CommandSyntax& syntax)
{
    Arguments a;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.rfind("--", 0) != 0 && !arg.empty() && a.m_positional.size() < syntax.maxPositional) {
            a.m_positional.push_back(arg);
            continue;
        }
        if (arg.rfind("--", 0) != 0 || arg.size() == 2)
            return makeError(ErrorCode::InvalidInput, "unexpected argument " + quotedForDisplay(arg));
        std::string name = arg.substr(2);
        std::optional<std::string> inlineValue;
        if (auto eq = name.find('='); eq != std::string::npos) { // --t=1/2
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (syntax.flags.count(name)) {
            if (inlineValue)
                return makeError(ErrorCode::InvalidInput, "--" + name + " takes no value");
            a.m_flags.insert(name);
            continue;
        }
        if (!syntax.valueOptions.count(name))
            return makeError(ErrorCode::InvalidInput, "unknown option " + quotedForDisplay("--" + name));
        std::string value;
        if (inlineValue) {
            value = *inlineValue;
        } else {
            // A value may itself start with '-' (a negative number), but not with "--".
            if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0)
                return makeError(ErrorCode::InvalidInput, "--" + name + " needs a value");
            value = args[++i];
        }
        auto& slot = a.m_values[name];
        if (!slot.empty() && !syntax.repeatable.count(name))
            return makeError(ErrorCode::InvalidInput, "--" + name + " given twice");
        slot.push_back(value);
    }
    return a;
}

std::optional<std::string> Arguments::value(const std::string& name) const
{
    auto it = m_values.find(name);
    if (it == m_values.end() || it->second.empty())
        return std::nullopt;
    return it->second.front();
}

std::vector<std::string> Arguments::values(const std::string& name) const
{
    auto it = m_values.find(name);
    return it == m_values.end() ? std::vector<std::string>{} : it->second;
}

Expected<Rational> Arguments::rational(const std::string& name, std::optional<Rational> fallback) const
{
    auto v = value(name);
    if (!v)
        return absent(name, fallback);
    auto q = parseRational(*v);
    if (!q)
        return makeError(ErrorCode::InvalidInput,
                         "--" + name + " " + quotedForDisplay(*v) + " " +
                             numberBeyondReach(*v).value_or("is not a finite number (integer, decimal or fraction p/q)"));
    return *q;
}

Expected<std::vector<Rational>> Arguments::rationalList(const std::string& name) const
{
    std::vector<Rational> out;
    auto v = value(name);
    if (!v)
        return out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = v->find(',', start);
        const std::string entry(
            trim(std::string_view(*v).substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        auto q = parseRational(entry);
        if (!q)
            return makeError(ErrorCode::InvalidInput,
                             "--" + name + ": entry " + std::to_string(out.size() + 1) + " " + quotedForDisplay(entry) + " " +
                                 numberBeyondReach(entry).value_or("is not a finite number (integer, decimal or fraction p/q)"));
        out.push_back(*q);
        if (comma == std::string::npos)
            return out;
        start = comma + 1;
    }
}

Expected<int> Arguments::integer(const std::string& name, int min, int max, std::optional<int> fallback) const
{
    auto v = value(name);
    if (!v)
        return absent(name, fallback);
    auto q = parseRational(*v);
    if (!q || q->get_den() != 1)
        return makeError(ErrorCode::InvalidInput,
                         "--" + name + " " + quotedForDisplay(*v) + " " +
                             (q ? "is not a whole number" : numberBeyondReach(*v).value_or("is not a whole number")));
    if (*q < min || *q > max)
        return makeError(ErrorCode::OutOfRange, "--" + name + " " + quotedForDisplay(*v) + " is out of range (" +
                                                    std::to_string(min) + " to " + std::to_string(max) + ")");
    return static_cast<int>(q->get_num().get_si());
}

Expected<std::string> Arguments::choice(const std::string& name, const std::vector<std::string>& choices,
                                        std::optional<std::string> fallback) const
{
    auto v = value(name);
    if (!v)
        return absent(name, fallback);
    for (const auto& c : choices)
        if (*v == c)
            return *v;
    std::string list;
    for (const auto& c : choices)
        list += (list.empty() ? "" : ", ") + c;
    return makeError(ErrorCode::InvalidInput, "--" + name + " " + quotedForDisplay(*v) + " is not one of: " + list);
}

Expected<std::vector<RPoint>> Arguments::points() const
{
    const auto inlinePoints = value("points");
    const auto file = value("points-file");
    if (inlinePoints && file)
        return makeError(ErrorCode::InvalidInput, "give either --points or --points-file, not both");
    if (inlinePoints)
        return parsePointList(*inlinePoints);
    if (!file)
        return makeError(ErrorCode::InvalidInput, "--points \"x,y;x,y;…\" or --points-file FILE is required");
    const auto text = readBoundedFile(*file, kMaxFileBytes); // it names the file
    if (!text)
        return text.error();
    auto points = parsePointFile(*text);
    if (!points)
        return makeError(points.error().code, quotedForDisplay(*file) + ": " + points.error().message);
    return points;
}

} // namespace granota::cli
