#pragma once
/// \file seed_trace.h
/// The trace CSV of the `seed` solver, in the layout of reference/seed_frog_trace.csv:
/// `step`, the body vertices `v0x,v0y … v{N−1}x,v{N−1}y` (vertex N, the copy of vertex 0,
/// is not repeated), then for each leg — front right, front left, back right, back
/// left — its elbow and wrist (`front_right_elbow_x,front_right_elbow_y,
/// front_right_wrist_x,front_right_wrist_y,…`). Row 0 is the initial state, row s the state
/// after s steps. Numbers are written as the shortest decimal that reads back to the same
/// R (Java's Float.toString style: "640.0", not "640"), so a float trace loses nothing.

#include "core/base/expected.h"
#include "core/softbody/seed/seed_frog.h"

#include <string>
#include <string_view>
#include <vector>

namespace granota {

/// The header line (no line break). Default: the reference's ten vertices and four legs.
std::string seedTraceHeader(int sides = 10, bool legs = true);
/// One row (no line break) for `frog` after `step` steps; the leg columns only when the
/// frog has legs. Matches seedTraceHeader(frog.body().sides(), !frog.legs().empty()).
template <class R> std::string seedTraceRow(int step, const SeedFrog<R>& frog);
/// The shortest decimal that reads back to exactly `value` ("640.0", "0.1", "1.0E-5").
std::string seedTraceNumber(float value);
std::string seedTraceNumber(double value);

struct SeedTrace {
    std::vector<std::string> columns;      ///< the header's names
    std::vector<std::vector<double>> rows; ///< one row per line after the header, step first
};

/// Parses a trace: a header of names and rows of numbers, all of the header's width.
/// Empty lines are skipped; anything else malformed is an InvalidInput error naming the
/// line. Numbers are read with std::from_chars (no locale); Java's "NaN" and "Infinity"
/// are read as such, so a broken reference is seen, not silently dropped.
Expected<SeedTrace> parseSeedTrace(std::string_view text);
/// Reads and parses a trace file.
Expected<SeedTrace> readSeedTrace(const std::string& path);

extern template std::string seedTraceRow<float>(int, const SeedFrog<float>&);
extern template std::string seedTraceRow<double>(int, const SeedFrog<double>&);

} // namespace granota
