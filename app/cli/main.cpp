// granota-cli: Granota's mathematics from the command line (docs/cli.md).
// Human-readable text by default, one JSON object with --json. Bad input: exit status 2
// and a line starting with "error:" on stderr — never a crash, never a NaN. An answer that
// cannot be written (a full disk, a closed pipe) is an error too, with the same status 2.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"
#include "app/cli/output_file.h"
#include "core/base/display_text.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>

using namespace granota;
using namespace granota::cli;

namespace {

constexpr int kFailed = 2; ///< every error: bad input, or an answer that cannot be written

std::vector<Command> commands()
{
    return {bezierCommand(),  bernsteinCommand(),  projectCommand(),         analyzeCommand(),
            fitCommand(),     catmullRomCommand(), kochanekBartelsCommand(), splineCommand(),
            bsplineCommand(), simulateCommand(),   benchCommand(),
#ifdef GRANOTA_HAS_REPORTS
            reportCommand(),
#endif
            demoCommand()};
}

void printUsage(std::ostream& out)
{
    out << "granota-cli — splines of the thesis \"Animació procedimental per a cossos tous\"\n\n"
           "usage: granota-cli COMMAND [options]\n\n";
    for (const Command& c : commands())
        out << "  " << c.name << "  " << c.usage << "\n      " << c.summary << "\n";
    out << "\nPoints: --points \"x,y;x,y;…\" (integers, decimals or fractions p/q) or --points-file F\n"
           "(CSV x,y lines or JSON [[x,y],…]). --exact prints exact fractions; --json prints JSON.\n"
           "Every error, bad input or an answer that cannot be written, exits with status 2 and\n"
           "one line \"error: …\" on stderr.\n";
}

int fail(const std::string& message)
{
    std::cerr << "error: " << message << "\n";
    return kFailed;
}

/// Flushes what went to stdout: 0, or the failed write said on stderr.
int finishOutput()
{
    std::cout.flush();
    if (std::cout)
        return 0;
    return fail(writeError("the output", errno).message);
}

} // namespace

int main(int argc, char* argv[])
{
    // A closed pipe (`granota-cli demo | head -c 10`) must be an error with a message and
    // status 2, not a silent death by SIGPIPE (status 141): ignored, a write to it fails
    // with EPIPE and finishOutput() says "cannot write the output: Broken pipe".
    std::signal(SIGPIPE, SIG_IGN);
    try {
        if (argc < 2) {
            std::cerr << "error: no command given\n";
            printUsage(std::cerr);
            return kFailed;
        }
        const std::string name = argv[1];
        if (name == "--help" || name == "-h" || name == "help") {
            errno = 0;
            printUsage(std::cout);
            return finishOutput();
        }
        for (const Command& c : commands()) {
            if (name != c.name)
                continue;
            std::vector<std::string> rest(argv + 2, argv + argc);
            for (const auto& a : rest)
                if (a == "--help" || a == "-h") {
                    errno = 0;
                    std::cout << "usage: granota-cli " << c.name << " " << c.usage << "\n  " << c.summary << "\n";
                    return finishOutput();
                }
            auto args = Arguments::parse(rest, c.syntax);
            if (!args)
                return fail(args.error().message);
            auto result = c.run(*args);
            if (!result)
                return fail(result.error().message);
            // The text shows the numbers of the JSON object: one check covers both forms.
            if (auto where = nonFiniteNumber(result->json))
                return fail(tooLargeForDouble("the answer's " + *where + " (as --json names it)",
                                              c.syntax.flags.count("exact") && !args->flag("exact"))
                                .message);
            errno = 0;
            if (args->flag("json"))
                std::cout << result->json.dump() << "\n";
            else
                std::cout << result->text;
            return finishOutput();
        }
        return fail("unknown command " + quotedForDisplay(name) + " (try granota-cli --help)");
    } catch (const std::bad_alloc&) {
        return fail("not enough memory for this input");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
