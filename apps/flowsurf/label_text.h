// flowsurf — text labels burnt into output images (compare sheets), rasterised with
// FreeType from a system font (Debian's fonts-dejavu-core).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::app {

// An RGB8 image, rows top to bottom.
struct RgbImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;
};

// Draws `text` with its baseline at (x, y) in `color`, `sizePx` high. Throws IoError if
// no font can be loaded.
void drawText(RgbImage& image, const std::string& text, int x, int y, int sizePx, const uint8_t color[3]);

}  // namespace flowsurf::app
