// flowsurf — writing what a Renderer read back: 8-bit RGB PNG (rows top to bottom) and H.264
// MP4 movies (through the `ffmpeg` program on PATH), written to a temporary file and
// renamed, so a reader never sees a partial file.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace flowsurf {

// Throws IoError naming the path (e.g. the folder does not exist).
void writePng(const std::string& path, int width, int height, const uint8_t* rgb);
// 16-bit gray, e.g. Renderer::readFlowTexture16.
void writePng16(const std::string& path, int width, int height, const uint16_t* gray);

// An MP4 (H.264) movie as `flowsurf render -o movie.mp4` writes it: frames of one size, RGB8,
// rows top to bottom. Throws IoError naming the path when ffmpeg is missing or fails.
class VideoWriter {
public:
    VideoWriter(const std::string& path, int width, int height, int fps = 30, int crf = 18);
    ~VideoWriter();  // without finish(): the partial movie is removed
    VideoWriter(VideoWriter&&) noexcept;
    VideoWriter& operator=(VideoWriter&&) noexcept;
    int width() const;
    int height() const;
    void addFrame(const uint8_t* rgb);  // width() * height() * 3 bytes
    void finish();                      // closes the stream and renames the movie into place

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace flowsurf
