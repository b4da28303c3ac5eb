// One libFuzzer target of the core: GRANOTA_FUZZ_TARGET names the property (properties.h).
#include "tests/fuzz/properties.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    granota::fuzz::trapOnFinding(granota::fuzz::checkCore(GRANOTA_FUZZ_TARGET, input), GRANOTA_FUZZ_TARGET);
    return 0;
}
