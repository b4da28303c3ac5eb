#include "core/base/bounded_file.h"

#include "core/base/display_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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
    const auto refused = [&name](int errnoValue) {
        Error e = makeError(ErrorCode::SystemRefused, "cannot read " + name + ": " + systemErrorText(errnoValue));
        e.systemError = errnoValue;
        return e;
    };
    // Opened without blocking, then looked at: opening a named pipe (FIFO) with no writer
    // would otherwise wait forever. Pipes and sockets are refused; a device such as
    // /dev/zero is read against the bound like a file.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return refused(errno);
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        const int e = errno;
        ::close(fd);
        return refused(e);
    }
    if (S_ISDIR(info.st_mode) || S_ISFIFO(info.st_mode) || S_ISSOCK(info.st_mode)) {
        ::close(fd);
        return makeError(ErrorCode::NotAFile,
                         name + (S_ISDIR(info.st_mode) ? " is a folder, not a file" : " is a pipe, not a file"));
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(::fdopen(fd, "rb"), &std::fclose);
    if (!file) {
        const int e = errno;
        ::close(fd);
        return refused(e);
    }
    std::string bytes;
    char buffer[1 << 16];
    while (bytes.size() <= maxBytes) {
        const std::size_t want = std::min(sizeof buffer, maxBytes + 1 - bytes.size());
        const std::size_t got = std::fread(buffer, 1, want, file.get());
        bytes.append(buffer, got);
        if (got < want) {
            if (std::ferror(file.get()))
                return refused(errno);
            break; // end of file
        }
    }
    if (bytes.size() > maxBytes)
        return makeError(ErrorCode::OutOfRange,
                         name + " is larger than " + byteSizeText(maxBytes) + ", the most Granota reads from one file");
    return bytes;
}

} // namespace granota
