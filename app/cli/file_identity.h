#pragma once
/// \file file_identity.h
/// Whether two of a command's file options name the same file. An output written over an
/// input destroys it (`simulate --replay r.json --trace r.json`), and two outputs on one
/// file mix their lines; the names alone do not tell (`c.csv` and `./c.csv`, a link), so
/// the files are compared by identity: the same device and inode when both exist, else the
/// same real folder and the same name. Every command checks this before it opens an output.

#include "core/base/expected.h"

#include <optional>
#include <string>
#include <vector>

namespace granota::cli {

/// Whether `a` and `b` name the same file. A character device (/dev/null) is never "the
/// same file" as itself: writing two outputs to it loses nothing.
bool sameFile(const std::string& a, const std::string& b);

/// A file option of a command and its value, when given: {"trace", args.value("trace")}.
struct FileOption {
    const char* option;
    std::optional<std::string> path;
};

/// An error "--A and --B name the same file" for the first two of `files` (in their order)
/// that do; success when no two do.
Expected<void> distinctFiles(const std::vector<FileOption>& files);

} // namespace granota::cli
