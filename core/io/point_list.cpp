#include "core/io/point_list.h"

#include "core/base/display_text.h"
#include "core/base/input_limits.h"
#include "core/base/text.h"
#include "core/io/json.h"

#include <string>

namespace granota {

namespace {

/// Text from a file or typed by a user inside a message: quoted, control characters escaped.
std::string quotedInput(std::string_view s) { return quotedForDisplay(s, 40); }

/// A file saved by a spreadsheet or Notepad may start with the UTF-8 byte-order mark
/// EF BB BF: it is not part of the first number.
std::string_view withoutByteOrderMark(std::string_view text)
{
    constexpr std::string_view kMark = "\xEF\xBB\xBF";
    if (text.substr(0, kMark.size()) == kMark)
        text.remove_prefix(kMark.size());
    return text;
}

/// The refusal of a list longer than kMaxDataPoints, the limit the GUI shares.
Error tooManyPoints(const char* holder)
{
    return makeError(ErrorCode::OutOfRange, std::string(holder) + " holds more than " + std::to_string(kMaxDataPoints) +
                                                " points, the most Granota reads");
}

Expected<Rational> coordinate(std::string_view text, std::size_t index, const char* axis)
{
    // Reading a number of n digits alone is superlinear in n (60 million digits: 17 s).
    if (const std::size_t chars = trim(text).size(); chars > kMaxNumberChars)
        return makeError(ErrorCode::OutOfRange, "point " + std::to_string(index) + ": " + axis + " is " + std::to_string(chars) +
                                                    " characters long, more than " + std::to_string(kMaxNumberChars) +
                                                    ", the longest number Granota reads: write fewer digits");
    auto q = parseRational(text);
    if (!q)
        return makeError(ErrorCode::InvalidInput, "point " + std::to_string(index) + ": " + axis + " = " +
                                                      quotedInput(trim(text)) + " " +
                                                      numberBeyondReach(text).value_or(
                                                          "is not a finite number (write integers, decimals or fractions p/q)"));
    return *q;
}

/// A coordinate of a JSON point: a number, read exactly from its text as written, or a
/// string holding one ("7/2"); anything else is refused as written.
Expected<Rational> jsonCoordinate(const Json& value, std::size_t index, const char* axis)
{
    if (const auto number = value.numberText())
        return coordinate(*number, index, axis);
    const std::string text = value.isString() ? *value.asString() : value.dump();
    return coordinate(text, index, axis);
}

Expected<RPoint> pair(std::string_view text, std::size_t index)
{
    const auto comma = text.find(',');
    if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos)
        return makeError(ErrorCode::InvalidInput,
                         "point " + std::to_string(index) + ": expected \"x,y\", got " + quotedInput(trim(text)));
    auto x = coordinate(text.substr(0, comma), index, "x");
    if (!x)
        return x.error();
    auto y = coordinate(text.substr(comma + 1), index, "y");
    if (!y)
        return y.error();
    return RPoint(*x, *y);
}

} // namespace

Expected<std::vector<RPoint>> parsePointList(std::string_view text)
{
    std::vector<RPoint> points;
    text = trim(text);
    if (text.empty())
        return makeError(ErrorCode::TooFewPoints, "no points given");
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(';', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view item = trim(text.substr(start, end - start));
        if (!item.empty() || end != text.size()) { // a trailing ';' is tolerated
            if (points.size() == kMaxDataPoints)
                return tooManyPoints("the list");
            auto p = pair(item, points.size());
            if (!p)
                return p.error();
            points.push_back(*p);
        }
        start = end + 1;
    }
    return points;
}

Expected<std::vector<RPoint>> parsePointCsv(std::string_view text)
{
    text = withoutByteOrderMark(text);
    std::vector<RPoint> points;
    std::size_t start = 0, lineNumber = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string_view line = trim(text.substr(start, end - start));
        start = end + 1;
        ++lineNumber;
        if (line.empty() || line.front() == '#')
            continue;
        auto p = pair(line, points.size());
        if (!p) {
            // A header such as "x,y" on the first line is not data.
            if (points.empty() && lineNumber == 1 && line.find_first_of("0123456789") == std::string_view::npos)
                continue;
            return makeError(p.error().code, "line " + std::to_string(lineNumber) + ": " + p.error().message);
        }
        if (points.size() == kMaxDataPoints)
            return tooManyPoints("the file");
        points.push_back(*p);
    }
    if (points.empty())
        return makeError(ErrorCode::TooFewPoints, "the file holds no points");
    return points;
}

Expected<std::vector<RPoint>> parsePointJson(std::string_view text)
{
    const auto bad = [](const std::string& what) {
        return makeError(ErrorCode::InvalidInput, "JSON points: " + what + " (expected [[x,y],…])");
    };
    auto doc = Json::parse(withoutByteOrderMark(text));
    if (!doc) {
        constexpr std::string_view kPrefix = "JSON: "; // Json::parse's, "JSON points: " here
        std::string what = doc.error().message;
        if (what.compare(0, kPrefix.size(), kPrefix) == 0)
            what.erase(0, kPrefix.size());
        return bad(what);
    }
    const Json::Array* list = doc->asArray();
    if (!list)
        return bad("the text is " + quotedInput(doc->dump()) + ", not a list");
    if (list->empty())
        return makeError(ErrorCode::TooFewPoints, "the file holds no points");
    if (list->size() > kMaxDataPoints)
        return tooManyPoints("the file");
    std::vector<RPoint> points;
    for (const Json& item : *list) {
        const std::size_t index = points.size();
        const Json::Array* xy = item.asArray();
        if (!xy || xy->size() != 2)
            return bad("point " + std::to_string(index) + " is " + quotedInput(item.dump()) + ", not a pair [x,y]");
        auto x = jsonCoordinate((*xy)[0], index, "x");
        if (!x)
            return x.error();
        auto y = jsonCoordinate((*xy)[1], index, "y");
        if (!y)
            return y.error();
        points.emplace_back(*x, *y);
    }
    return points;
}

Expected<std::vector<RPoint>> parsePointFile(std::string_view text)
{
    const std::string_view t = trim(withoutByteOrderMark(text));
    if (!t.empty() && t.front() == '[')
        return parsePointJson(t);
    return parsePointCsv(text);
}

} // namespace granota
