#include "app/cli/output_file.h"

#include "core/base/display_text.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace granota::cli {

Error writeError(const std::string& what, int errnoValue)
{
    return makeError(ErrorCode::InvalidInput,
                     "cannot write " + what + ": " + (errnoValue != 0 ? systemErrorText(errnoValue) : "the write failed"));
}

Expected<void> writeFile(const std::string& path, std::string_view bytes)
{
    const std::string name = quotedForDisplay(path);
    errno = 0;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return writeError(name, errno);
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const int writeErrno = errno;
    // fclose flushes the buffer: a full disk often shows only here.
    errno = 0;
    const bool closed = std::fclose(file) == 0;
    if (!written)
        return writeError(name, writeErrno);
    if (!closed)
        return writeError(name, errno);
    return {};
}

} // namespace granota::cli
