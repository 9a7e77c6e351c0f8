// Dye file JSON (--dye-file): sources or a typed error.
#include "core/errors.h"
#include "fuzz_input.h"
#include "session/options/dye_sources.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        flowsurf::session::readDyeFile(fuzzInputFile(data, size, ".json"));
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
