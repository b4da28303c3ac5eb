#include "app/cli/file_identity.h"

#include <climits>
#include <cstdlib>
#include <sys/stat.h>

namespace granota::cli {

namespace {

/// The real path of the folder holding `path`, a slash and its last name; `path` itself
/// when the folder cannot be resolved (it does not exist: nothing can be written there).
std::string realFolderAndName(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    char resolved[PATH_MAX];
    if (name.empty() || name == "." || name == ".." || !::realpath(folder.c_str(), resolved))
        return path;
    return std::string(resolved) + "/" + name;
}

} // namespace

bool sameFile(const std::string& a, const std::string& b)
{
    struct stat infoA {};
    struct stat infoB {};
    const bool existsA = ::stat(a.c_str(), &infoA) == 0;
    const bool existsB = ::stat(b.c_str(), &infoB) == 0;
    if (existsA && existsB)
        return infoA.st_dev == infoB.st_dev && infoA.st_ino == infoB.st_ino && !S_ISCHR(infoA.st_mode);
    if (existsA != existsB)
        return false; // one exists, the other not: two files
    return realFolderAndName(a) == realFolderAndName(b);
}

Expected<void> distinctFiles(const std::vector<FileOption>& files)
{
    for (std::size_t i = 0; i < files.size(); ++i)
        for (std::size_t j = i + 1; j < files.size(); ++j)
            if (files[i].path && files[j].path && sameFile(*files[i].path, *files[j].path))
                return makeError(ErrorCode::InvalidInput,
                                 std::string("--") + files[i].option + " and --" + files[j].option + " name the same file");
    return {};
}

} // namespace granota::cli
