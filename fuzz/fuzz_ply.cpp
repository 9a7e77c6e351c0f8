// PLY parser (ASCII and binary): any input gives a mesh or a typed error, nothing else.
#include "core/errors.h"
#include "fuzz_input.h"
#include "io/reader/parsers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        flowsurf::io::detail::readPly(fuzzInputFile(data, size, ".ply"));
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
