// One libFuzzer target that needs the widgets: GRANOTA_FUZZ_TARGET names the property
// (ui_properties.h). The QApplication runs on the offscreen platform and nothing is shown.
#include "tests/fuzz/properties.h"
#include "tests/fuzz/ui_properties.h"

#include <QApplication>

#include <cstddef>
#include <cstdint>

// Fontconfig keeps an allocation of its first font look-up unreachable: its leak, not ours.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    qputenv("QT_SCALE_FACTOR", "1");
    // Its own arguments: libFuzzer's flags are not Qt's business.
    static int argc = 1;
    static char name[] = "fuzz_" GRANOTA_FUZZ_TARGET;
    static char* argv[] = {name, nullptr};
    static QApplication* const app = new QApplication(argc, argv); // lives until exit
    (void)app;
    granota::fuzz::initUi();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    granota::fuzz::trapOnFinding(granota::fuzz::checkUi(GRANOTA_FUZZ_TARGET, input), GRANOTA_FUZZ_TARGET);
    return 0;
}
