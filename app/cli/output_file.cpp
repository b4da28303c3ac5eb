#include "app/cli/output_file.h"

#include "core/base/display_text.h"
#include "core/base/file_replacement.h"

namespace granota::cli {

Error writeError(const std::string& what, int errnoValue)
{
    return makeError(ErrorCode::InvalidInput,
                     "cannot write " + what + ": " + (errnoValue != 0 ? systemErrorText(errnoValue) : "the write failed"));
}

Expected<void> writeFile(const std::string& path, std::string_view bytes) { return replaceFile(path, bytes); }

} // namespace granota::cli
