#pragma once
/// \file input_limits.h
/// How much Granota reads, and how much work one request may ask for, in one place
/// (docs/extreme-cases.md lists them all). Every file Granota opens (a document, a data
/// file to fit, a --points-file) is read with readBoundedFile() against kMaxFileBytes,
/// and every list of points against kMaxDataPoints, so that whatever Granota saves it
/// can open again: a document holds at most kMaxDataPoints data points, about 105 bytes
/// each once written, far below kMaxFileBytes. The work limits below bound what a small
/// request can ask for (a 114-byte document, a few command-line words): each is refused,
/// with a message naming what to lower, before any of the work is done.

#include <cstddef>

namespace granota {

/// The largest file Granota reads: documents, CSV/JSON point files, autosaves.
constexpr std::size_t kMaxFileBytes = 64u * 1024u * 1024u;
/// The most points a list may hold (a fit's data points, an imported file).
constexpr std::size_t kMaxDataPoints = 200000;
/// The longest coordinate a list of points may hold, in characters: a million digits
/// (about 3.3 million bits) read in a fraction of a second, where converting 60 million
/// took 17 s before anything else was done. An exact computation on the numbers read is
/// bounded further by its own estimate (core/exact/exact_cost.h).
constexpr std::size_t kMaxNumberChars = 1000000;

/// The most soft-body vertices one scene holds, every body together (bodies × sides, or
/// × the Bézier points of §4.9), and `granota-cli bench` over all its copies: 5000 bodies
/// of 10000 sides would be 50 million vertices, gigabytes and minutes just to build.
constexpr long kMaxVertices = 100000;

/// The most curve samples one command writes, every segment together (`catmull-rom
/// --samples S` on k segments is k × S): about 250 bytes and 3.4 µs each as JSON on the
/// reference machine, so at most about 250 MB and 4 s (1000 points × 100 000 samples
/// reached 17 GB before).
constexpr long kMaxCurveSamples = 1000000;

/// The most interpolations (1 − t)·a + t·b that building the §4.9 body may take: its
/// `bezier_samples` points are sampled once by De Casteljau (Def 2.4) from the closed
/// control polygon of `sides` + 1 points, sides·(sides + 1)/2 interpolations a point
/// (softbody/outline.h, bezierBodyPointsWork). About 0.9 ns each on the reference machine:
/// half a second at most, where 10 000 sides and 2000 points (10¹¹) froze the window 48 s.
constexpr double kMaxBezierOutlineWork = 5e8;

/// The most work one `granota-cli simulate` or `bench` run may ask for, in estimated
/// nanoseconds on the reference machine (softbody/step_cost.h: steps × the estimated time
/// of a step, which counts the substeps and the work that grows faster than the vertices):
/// two minutes. `bounce --solver stable --set sides=10000 --steps 100000` (3 hours) is
/// refused; the frog's 600 default steps are about 14 ms.
constexpr double kMaxRunNanoseconds = 120e9;

} // namespace granota
