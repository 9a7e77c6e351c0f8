#include <flowsurf/image.h>

#include "core/errors.h"
#include "io/image_writer.h"

#include <vector>

namespace flowsurf {

void writePng(const std::string& path, int width, int height, const uint8_t* rgb) {
    if (width <= 0 || height <= 0) throw ConfigError(path + ": image size must be positive");
    io::writePngRgb8(path, width, height, 3, std::vector<uint8_t>(rgb, rgb + size_t(width) * height * 3));
}

void writePng16(const std::string& path, int width, int height, const uint16_t* gray) {
    if (width <= 0 || height <= 0) throw ConfigError(path + ": image size must be positive");
    io::writePngGray16(path, width, height, std::vector<uint16_t>(gray, gray + size_t(width) * height));
}

}  // namespace flowsurf
