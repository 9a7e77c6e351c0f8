// flowsurf — text burnt into images (compare sheets' labels, the legend), rasterised with
// FreeType from a system font (Debian's fonts-dejavu-core) or the copy a portable tree carries
// (share/flowsurf/fonts/). CPU only, no GL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::methods {

// An 8-bit image, rows top to bottom: RGB (channels 3) or RGBA (channels 4).
struct RgbImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;
    int channels = 3;
};

// Draws `text` with its baseline at (x, y) in `color`, `sizePx` high. On RGBA images the
// glyph coverage also raises alpha. Throws IoError if no font can be loaded.
void drawText(RgbImage& image, const std::string& text, int x, int y, int sizePx, const uint8_t color[3]);
// The advance width of `text` in pixels at `sizePx`.
int textWidth(const std::string& text, int sizePx);

}  // namespace flowsurf::methods
