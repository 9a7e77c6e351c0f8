// flowsurf — PNG output through libpng. Writes go to a temporary file in the same
// folder and are renamed on success: a failed write leaves no partial output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::io {

// 8-bit RGB or RGBA, rows top to bottom. Throws IoError.
void writePngRgb8(const std::string& path, int width, int height, int channels,
                  const std::vector<uint8_t>& pixels);

// 16-bit gray, rows top to bottom. Throws IoError.
void writePngGray16(const std::string& path, int width, int height,
                    const std::vector<uint16_t>& pixels);

// For tests: reads an 8-bit RGB(A) or 16-bit gray PNG back. Throws IoError/FormatError.
struct PngImage {
    int width = 0, height = 0, channels = 0, bitDepth = 0;
    std::vector<uint16_t> samples;  // width*height*channels, rows top to bottom
};
PngImage readPng(const std::string& path);

}  // namespace flowsurf::io
