#pragma once
/// \file point_list.h
/// Reading points typed by a user or stored in a file (docs/cli.md):
///  - inline:  "x,y;x,y;…"           e.g. "2,3;-1,8;-5/2,0.5"
///  - CSV:     one "x,y" per line     (blank lines and lines starting with # ignored,
///                                     a first line of column names is skipped)
///  - JSON:    [[x,y],[x,y],…]        (JSON numbers, or strings holding fractions "p/q")
/// Every coordinate is read as the exact rational it denotes (integers, fractions p/q,
/// decimals, exponents), so that exact computations get exactly what was typed.
/// NaN, infinities and anything else is an error naming the offending point; the text
/// quoted in it has its control characters escaped (quotedForDisplay). A file may start
/// with a UTF-8 byte-order mark. A list holds at most kMaxDataPoints points
/// (core/base/input_limits.h), the limit the CLI and the GUI share.

#include "core/base/expected.h"
#include "core/exact/rational.h"

#include <string_view>
#include <vector>

namespace granota {

Expected<std::vector<RPoint>> parsePointList(std::string_view text);
Expected<std::vector<RPoint>> parsePointCsv(std::string_view text);
Expected<std::vector<RPoint>> parsePointJson(std::string_view text);
/// JSON if the text starts with '[', CSV otherwise.
Expected<std::vector<RPoint>> parsePointFile(std::string_view text);

} // namespace granota
