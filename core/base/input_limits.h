#pragma once
/// \file input_limits.h
/// How much Granota reads, in one place. Every file Granota opens (a document, a data
/// file to fit, a --points-file) is read with readBoundedFile() against kMaxFileBytes,
/// and every list of points against kMaxDataPoints, so that whatever Granota saves it
/// can open again: a document holds at most kMaxDataPoints data points, about 105 bytes
/// each once written, far below kMaxFileBytes.

#include <cstddef>

namespace granota {

/// The largest file Granota reads: documents, CSV/JSON point files, autosaves.
constexpr std::size_t kMaxFileBytes = 64u * 1024u * 1024u;
/// The most points a list may hold (a fit's data points, an imported file).
constexpr std::size_t kMaxDataPoints = 200000;

} // namespace granota
