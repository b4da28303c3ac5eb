#include "core/base/bounded_file.h"

#include "core/base/display_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

namespace granota {

std::string byteSizeText(std::size_t bytes)
{
    constexpr std::size_t kMiB = 1024u * 1024u;
    if (bytes >= kMiB && bytes % kMiB == 0)
        return std::to_string(bytes / kMiB) + " MB";
    return std::to_string(bytes) + " bytes";
}

Expected<std::string> readBoundedFile(const std::string& path, std::size_t maxBytes)
{
    const std::string name = quotedForDisplay(path);
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0)
        return makeError(ErrorCode::InvalidInput, "cannot read " + name + ": " + systemErrorText(errno));
    if (S_ISDIR(info.st_mode))
        return makeError(ErrorCode::InvalidInput, name + " is a folder, not a file");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file)
        return makeError(ErrorCode::InvalidInput, "cannot read " + name + ": " + systemErrorText(errno));
    std::string bytes;
    char buffer[1 << 16];
    while (bytes.size() <= maxBytes) {
        const std::size_t want = std::min(sizeof buffer, maxBytes + 1 - bytes.size());
        const std::size_t got = std::fread(buffer, 1, want, file.get());
        bytes.append(buffer, got);
        if (got < want) {
            if (std::ferror(file.get()))
                return makeError(ErrorCode::InvalidInput, "cannot read " + name + ": " + systemErrorText(errno));
            break; // end of file
        }
    }
    if (bytes.size() > maxBytes)
        return makeError(ErrorCode::OutOfRange,
                         name + " is larger than " + byteSizeText(maxBytes) + ", the most Granota reads from one file");
    return bytes;
}

} // namespace granota
