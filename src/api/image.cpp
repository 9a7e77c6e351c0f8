#include <flowsurf/image.h>

#include "core/errors.h"
#include "io/image_writer.h"
#include "io/video_writer.h"

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

struct VideoWriter::Impl {
    io::VideoWriter writer;
    int width, height;
};

VideoWriter::VideoWriter(const std::string& path, int width, int height, int fps, int crf) {
    if (width <= 0 || height <= 0) throw ConfigError(path + ": video size must be positive");
    if (fps < 1 || fps > 240) throw ConfigError(path + ": fps " + std::to_string(fps) + " is out of range 1..240");
    if (crf < 0 || crf > 51) throw ConfigError(path + ": crf " + std::to_string(crf) + " is out of range 0..51");
    // io::VideoWriter is not movable: built in place.
    impl_.reset(new Impl{io::VideoWriter(path, width, height, io::VideoOptions{fps, crf}), width, height});
}
VideoWriter::~VideoWriter() = default;
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;

int VideoWriter::width() const { return impl_->width; }
int VideoWriter::height() const { return impl_->height; }

void VideoWriter::addFrame(const uint8_t* rgb) {
    impl_->writer.addFrame(std::vector<uint8_t>(rgb, rgb + size_t(impl_->width) * impl_->height * 3));
}

void VideoWriter::finish() { impl_->writer.finish(); }

}  // namespace flowsurf
