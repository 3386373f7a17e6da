// libFuzzer target: the JSON scene loader must turn any bytes into a scene or one
// rt::Error, never a crash, a hang or a sanitizer report.
#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzz_load(data, size, ".json");
}
