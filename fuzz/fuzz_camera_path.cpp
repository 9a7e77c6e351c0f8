// Camera path JSON (--camera-path): a path or a typed error.
#include "core/errors.h"
#include "fuzz_input.h"
#include "session/camera_path_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        flowsurf::session::readCameraPath(fuzzInputFile(data, size, ".json"), flowsurf::core::Camera{});
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
