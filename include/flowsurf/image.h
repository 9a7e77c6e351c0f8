// flowsurf — writing what a Renderer read back: 8-bit RGB PNG (rows top to bottom), written
// to a temporary file and renamed, so a reader never sees a partial file.
#pragma once

#include <cstdint>
#include <string>

namespace flowsurf {

// Throws IoError naming the path (e.g. the folder does not exist).
void writePng(const std::string& path, int width, int height, const uint8_t* rgb);
// 16-bit gray, e.g. Renderer::readFlowTexture16.
void writePng16(const std::string& path, int width, int height, const uint16_t* gray);

}  // namespace flowsurf
