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
    return makeError(ErrorCode::OutOfRange,
                     std::string(holder) + " holds more than " + std::to_string(kMaxDataPoints) +
                         " points, the most Granota reads",
                     MessageId::TooManyPoints, {numberArg(static_cast<double>(kMaxDataPoints))});
}

Error noPoints(const char* english, MessageId id) { return makeError(ErrorCode::TooFewPoints, english, id, {}); }

Expected<Rational> coordinate(std::string_view text, std::size_t index, const char* axis)
{
    const MessageArg point = numberArg(static_cast<double>(index));
    // Reading a number of n digits alone is superlinear in n (60 million digits: 17 s).
    if (const std::size_t chars = trim(text).size(); chars > kMaxNumberChars)
        return makeError(
            ErrorCode::OutOfRange,
            "point " + std::to_string(index) + ": " + axis + " is " + std::to_string(chars) + " characters long, more than " +
                std::to_string(kMaxNumberChars) + ", the longest number Granota reads: write fewer digits",
            MessageId::CoordinateTooLong,
            {point, textArg(axis), numberArg(static_cast<double>(chars)), numberArg(static_cast<double>(kMaxNumberChars))});
    auto q = parseRational(text);
    if (!q) {
        const std::string shown = quotedInput(trim(text));
        const auto beyond = numberBeyondReach(text);
        const MessageId id = !beyond                                          ? MessageId::CoordinateNotANumber
                             : beyond->find("too large") != std::string::npos ? MessageId::CoordinateTooLarge
                                                                              : MessageId::CoordinateTooSmall;
        return makeError(ErrorCode::InvalidInput,
                         "point " + std::to_string(index) + ": " + axis + " = " + shown + " " +
                             beyond.value_or("is not a finite number (write integers, decimals or fractions p/q)"),
                         id, {point, textArg(axis), textArg(shown)});
    }
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

/// How the two numbers of a CSV line are written: "x,y" with decimal points, or as a
/// spreadsheet in a language with a decimal comma saves them, "x;y" with decimal commas
/// (LibreOffice and Excel in Catalan, Spanish, French…), or x and y separated by a tab.
struct CsvColumns {
    char separator = ',';
    bool decimalComma = false; ///< a ',' inside a number is its decimal sign
};

/// The columns of one CSV line: ';' if it has one, else a tab if it has one, else ','.
/// Beside ';' or a tab, a comma can only be a decimal sign.
CsvColumns csvColumns(std::string_view line)
{
    if (line.find(';') != std::string_view::npos)
        return {';', true};
    if (line.find('\t') != std::string_view::npos)
        return {'\t', true};
    return {',', false};
}

Expected<RPoint> pair(std::string_view text, std::size_t index, CsvColumns columns = {})
{
    const auto at = text.find(columns.separator);
    if (at == std::string_view::npos || text.find(columns.separator, at + 1) != std::string_view::npos)
        return makeError(ErrorCode::InvalidInput,
                         "point " + std::to_string(index) + ": expected \"x,y\", got " + quotedInput(trim(text)),
                         MessageId::PointNotAPair, {numberArg(static_cast<double>(index)), textArg(quotedInput(trim(text)))});
    auto number = [&](std::string_view part, const char* axis) {
        if (!columns.decimalComma)
            return coordinate(part, index, axis);
        std::string pointed(part);
        for (char& c : pointed)
            if (c == ',')
                c = '.';
        auto read = coordinate(pointed, index, axis);
        if (!read) // quote the number as written, with its comma
            return coordinate(part, index, axis);
        return read;
    };
    auto x = number(text.substr(0, at), "x");
    if (!x)
        return x.error();
    auto y = number(text.substr(at + 1), "y");
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
        return noPoints("no points given", MessageId::NoPointsGiven);
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
        auto p = pair(line, points.size(), csvColumns(line));
        if (!p) {
            // A header such as "x,y" on the first line is not data.
            if (points.empty() && lineNumber == 1 && line.find_first_of("0123456789") == std::string_view::npos)
                continue;
            Error e = withContext("line " + std::to_string(lineNumber) + ": ", p.error());
            e.line = static_cast<long>(lineNumber);
            return e;
        }
        if (points.size() == kMaxDataPoints)
            return tooManyPoints("the file");
        points.push_back(*p);
    }
    if (points.empty())
        return noPoints("the file holds no points", MessageId::FileHoldsNoPoints);
    return points;
}

Expected<std::vector<RPoint>> parsePointJson(std::string_view text)
{
    const auto bad = [](const std::string& what, MessageId id, std::vector<MessageArg> args) {
        return makeError(ErrorCode::InvalidInput, "JSON points: " + what + " (expected [[x,y],…])", id, std::move(args));
    };
    auto doc = Json::parse(withoutByteOrderMark(text));
    if (!doc) {
        constexpr std::string_view kPrefix = "JSON: "; // Json::parse's, "JSON points: " here
        std::string what = doc.error().message;
        if (what.compare(0, kPrefix.size(), kPrefix) == 0)
            what.erase(0, kPrefix.size());
        return bad(what, MessageId::JsonPointsNotJson, {});
    }
    const Json::Array* list = doc->asArray();
    if (!list)
        return bad("the text is " + quotedInput(doc->dump()) + ", not a list", MessageId::JsonPointsNotAList,
                   {textArg(quotedInput(doc->dump()))});
    if (list->empty())
        return noPoints("the file holds no points", MessageId::FileHoldsNoPoints);
    if (list->size() > kMaxDataPoints)
        return tooManyPoints("the file");
    std::vector<RPoint> points;
    for (const Json& item : *list) {
        const std::size_t index = points.size();
        const Json::Array* xy = item.asArray();
        if (!xy || xy->size() != 2)
            return bad("point " + std::to_string(index) + " is " + quotedInput(item.dump()) + ", not a pair [x,y]",
                       MessageId::JsonPointNotAPair, {numberArg(static_cast<double>(index)), textArg(quotedInput(item.dump()))});
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
