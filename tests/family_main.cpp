// The main() of a family of test files (tests/test_main.h): the first argument names the
// test file to run, the rest go to Qt Test. With no name, or an unknown one, it lists the
// tests it holds and exits with 2.
#include "tests/test_main.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace {

std::vector<std::pair<std::string, granota::test::TestMain>>& registry()
{
    static std::vector<std::pair<std::string, granota::test::TestMain>> tests;
    return tests;
}

std::string baseName(const char* path)
{
    std::string name(path);
    const auto slash = name.find_last_of("/\\");
    if (slash != std::string::npos)
        name.erase(0, slash + 1);
    const auto dot = name.rfind('.');
    if (dot != std::string::npos)
        name.erase(dot);
    return name;
}

} // namespace

granota::test::Registration::Registration(const char* sourceFile, TestMain main)
{
    registry().emplace_back(baseName(sourceFile), main);
}

int main(int argc, char* argv[])
{
    auto& tests = registry();
    std::sort(tests.begin(), tests.end());
    if (argc >= 2) {
        for (const auto& [name, testMain] : tests) {
            if (name == argv[1]) {
                // Qt Test gets the family's path as its program (applicationDirPath() stays
                // build/tests) and the arguments after the name.
                argv[1] = argv[0];
                return testMain(argc - 1, argv + 1);
            }
        }
        std::fprintf(stderr, "error: no test named '%s' in %s\n", argv[1], argv[0]);
    }
    std::fprintf(stderr, "usage: %s TEST [Qt Test options and functions]\ntests:\n", argv[0]);
    for (const auto& entry : tests)
        std::fprintf(stderr, "  %s\n", entry.first.c_str());
    return 2;
}
