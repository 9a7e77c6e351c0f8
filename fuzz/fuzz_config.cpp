// Config file JSON (--config): options applied, or a typed error; what applies round-trips.
#include "core/errors.h"
#include "fuzz_input.h"
#include "session/options/config_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    flowsurf::session::RenderOptions o;
    try {
        flowsurf::session::applyConfigFile(fuzzInputFile(data, size, ".json"), o);
        (void)flowsurf::session::configJson(o);
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
