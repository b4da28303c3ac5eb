#include "core/base/file_replacement.h"

#include "core/base/display_text.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace granota {

namespace {

constexpr std::size_t kBufferBytes = 64u * 1024u;

/// The file a path finally names: a symbolic link's target is replaced, not the link.
std::string resolvedTarget(const std::string& path)
{
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode))
        return path;
    char resolved[PATH_MAX];
    return ::realpath(path.c_str(), resolved) ? std::string(resolved) : path; // a dangling link is replaced
}

std::string folderOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The permissions a new file gets from open(2): 0666 less the process's umask.
mode_t newFileMode()
{
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

/// write(2) until every byte is written: a short write is retried, an error returned.
int writeAll(int fd, std::string_view bytes)
{
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        if (n == 0)
            return EIO;
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return 0;
}

} // namespace

Error fileWriteError(const std::string& path, int errnoValue)
{
    Error e = makeError(ErrorCode::SystemRefused, "cannot write " + quotedForDisplay(path) + ": " +
                                                      (errnoValue != 0 ? systemErrorText(errnoValue) : "the write failed"));
    e.systemError = errnoValue;
    return e;
}

Expected<FileReplacement> FileReplacement::open(const std::string& path)
{
    FileReplacement out;
    out.m_target = resolvedTarget(path);
    struct stat info {};
    const bool exists = ::stat(out.m_target.c_str(), &info) == 0;
    if (exists && S_ISDIR(info.st_mode))
        return fileWriteError(path, EISDIR);
    if (exists && !S_ISREG(info.st_mode)) { // a device or a pipe: written in place
        out.m_fd = ::open(out.m_target.c_str(), O_WRONLY | O_CLOEXEC);
        if (out.m_fd < 0)
            return fileWriteError(path, errno);
        out.m_target = path;
        return out;
    }
    std::string pattern = folderOf(out.m_target) + "/." + nameOf(out.m_target) + ".XXXXXX";
    out.m_fd = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (out.m_fd < 0)
        return fileWriteError(path, errno);
    out.m_hidden = pattern;
    // mkostemp makes the file 0600: give it the old file's permissions, or a new file's.
    ::fchmod(out.m_fd, exists ? (info.st_mode & 07777) : newFileMode());
    return out;
}

FileReplacement::FileReplacement(FileReplacement&& other) noexcept
    : m_target(std::move(other.m_target)), m_hidden(std::exchange(other.m_hidden, std::string())),
      m_fd(std::exchange(other.m_fd, -1)), m_written(other.m_written), m_buffer(std::move(other.m_buffer)),
      m_failed(other.m_failed)
{
}

FileReplacement& FileReplacement::operator=(FileReplacement&& other) noexcept
{
    if (this != &other) {
        discard();
        m_target = std::move(other.m_target);
        m_hidden = std::exchange(other.m_hidden, std::string());
        m_fd = std::exchange(other.m_fd, -1);
        m_written = other.m_written;
        m_buffer = std::move(other.m_buffer);
        m_failed = other.m_failed;
    }
    return *this;
}

FileReplacement::~FileReplacement() { discard(); }

void FileReplacement::discard()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
    if (!m_hidden.empty())
        ::unlink(m_hidden.c_str());
    m_hidden.clear();
}

Expected<void> FileReplacement::fail(int errnoValue)
{
    if (m_failed == 0)
        m_failed = errnoValue != 0 ? errnoValue : EIO;
    discard();
    return fileWriteError(m_target, m_failed);
}

Expected<void> FileReplacement::flushBuffer()
{
    if (const int e = writeAll(m_fd, m_buffer))
        return fail(e);
    m_written += m_buffer.size();
    m_buffer.clear();
    return {};
}

Expected<void> FileReplacement::write(std::string_view bytes)
{
    if (m_failed != 0 || m_fd < 0)
        return fileWriteError(m_target, m_failed != 0 ? m_failed : EBADF);
    m_buffer.append(bytes);
    if (m_buffer.size() >= kBufferBytes)
        return flushBuffer();
    return {};
}

Expected<void> FileReplacement::commit()
{
    if (m_failed != 0 || m_fd < 0)
        return fileWriteError(m_target, m_failed != 0 ? m_failed : EBADF);
    if (auto flushed = flushBuffer(); !flushed)
        return flushed;
    if (m_hidden.empty()) { // written in place
        const int fd = std::exchange(m_fd, -1);
        if (::close(fd) != 0 && errno != EINTR)
            return fail(errno);
        return {};
    }
    // A disk that reports its errors late (NFS, a quota) reports them here.
    if (::fsync(m_fd) != 0 && errno != EINVAL)
        return fail(errno);
    struct stat info {};
    if (::fstat(m_fd, &info) != 0)
        return fail(errno);
    if (static_cast<std::uint64_t>(info.st_size) != m_written)
        return fail(ENOSPC);
    const int fd = std::exchange(m_fd, -1);
    if (::close(fd) != 0 && errno != EINTR)
        return fail(errno);
    if (::rename(m_hidden.c_str(), m_target.c_str()) != 0)
        return fail(errno);
    m_hidden.clear();
    // The rename itself reaches the disk with the folder.
    const int folder = ::open(folderOf(m_target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
    return {};
}

Expected<void> replaceFile(const std::string& path, std::string_view bytes)
{
    auto file = FileReplacement::open(path);
    if (!file)
        return file.error();
    if (auto written = file->write(bytes); !written)
        return written;
    return file->commit();
}

} // namespace granota
