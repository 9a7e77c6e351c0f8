// flowsurf — H.264 MP4 output through the `ffmpeg` program (raw RGB frames on a pipe).
// The video is written to a temporary file and renamed by finish(); if the writer is
// destroyed without finish() (an error mid-run), the temporary is removed.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace flowsurf::io {

struct VideoOptions {
    int fps = 30;   // frames per second
    int crf = 18;   // H.264 constant rate factor, 0 (lossless) .. 51
};

class VideoWriter {
public:
    // Throws IoError when ffmpeg cannot be started or the size is not encodable.
    VideoWriter(const std::string& path, int width, int height, const VideoOptions& options = {});
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // One RGB8 frame, rows top to bottom. Throws IoError.
    void addFrame(const std::vector<uint8_t>& rgb);
    // Closes the stream, checks ffmpeg's exit status, renames into place. Throws IoError.
    void finish();

private:
    std::string path_, tmpPath_;
    int width_, height_;
    FILE* pipe_ = nullptr;
    int frames_ = 0;
};

}  // namespace flowsurf::io
