// EnSight Gold pre-check (ASCII and C binary geometry): any geometry file passes or is
// refused with a typed error, quickly, whatever counts it declares.
#include "core/errors.h"
#include "fuzz_input.h"
#include "io/reader/ensight_check.h"

#include <cstdio>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string geometry = fuzzInputFile(data, size, ".geo");
    static const std::string casePath = [&] {
        const std::string path = geometry.substr(0, geometry.size() - 4) + ".case";
        if (FILE* f = std::fopen(path.c_str(), "w")) {
            const std::string name = geometry.substr(geometry.rfind('/') + 1);
            std::fprintf(f, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: %s\n", name.c_str());
            std::fclose(f);
        }
        return path;
    }();
    try {
        flowsurf::io::detail::checkEnSightCase(casePath);
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
