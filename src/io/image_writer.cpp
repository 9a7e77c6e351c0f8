// PNG through libpng. libpng reports errors by longjmp, so the libpng calls live in
// small functions with only plain locals (no destructors skipped); they return false
// with libpng's message, and the C++ callers turn that into exceptions.
#include "io/image_writer.h"

#include "core/errors.h"
#include "io/temp_file.h"

#include <png.h>

#include <bit>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <system_error>

namespace flowsurf::io {

namespace {

struct PngStatus {
    char message[256] = "";
};

void onPngError(png_structp png, png_const_charp msg) {
    auto* status = static_cast<PngStatus*>(png_get_error_ptr(png));
    std::snprintf(status->message, sizeof status->message, "%s", msg ? msg : "libpng error");
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // e.g. ancillary chunk issues: harmless

struct PngLayout {
    int width, height, colorType, bitDepth;
};

bool encodePng(FILE* file, const PngLayout& layout, png_bytep* rows, PngStatus& status) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &status, onPngError, onPngWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, layout.width, layout.height, layout.bitDepth, layout.colorType,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    // PNG stores 16-bit samples big-endian; ours are in host order.
    if (layout.bitDepth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

void writePng(const std::string& path, const PngLayout& layout, const uint8_t* data,
              size_t rowBytes) {
    detail::TempFile tmp(path);
    FILE* file = fdopen(tmp.fd(), "wb");
    if (!file) throw IoError(detail::writeErrorMessage(path, errno));
    tmp.fd() = -1;  // the FILE owns the descriptor now

    std::vector<png_bytep> rows(static_cast<size_t>(layout.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = const_cast<png_bytep>(data + y * rowBytes);
    PngStatus status;
    errno = 0;
    bool ok = encodePng(file, layout, rows.data(), status);
    int err = errno;
    if (std::fflush(file) != 0 && ok) {
        ok = false;
        err = errno;
    }
    if (std::fclose(file) != 0 && ok) {
        ok = false;
        err = errno;
    }
    if (!ok) {
        // A failed fwrite (disk full) reaches us as libpng's "Write Error"; errno says why.
        std::string reason = err ? std::system_category().message(err) : status.message;
        throw IoError(path + ": cannot write PNG (" + reason + ")");
    }
    tmp.commit();
}

void checkSize(const std::string& path, int width, int height, int channels, size_t samples) {
    if (width <= 0 || height <= 0 || size_t(width) * size_t(height) * size_t(channels) != samples)
        throw IoError(path + ": cannot write a " + std::to_string(width) + "x" +
                      std::to_string(height) + " image with " + std::to_string(channels) +
                      " channels from " + std::to_string(samples) + " samples");
}

// Reading: expanded to 8-bit (palette, low-bit gray) or kept at 16; host byte order.
bool decodePng(FILE* file, PngImage& image, std::vector<uint8_t>& bytes, PngStatus& status) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &status, onPngError, onPngWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    png_set_expand(png);
    const int passes = png_set_interlace_handling(png);  // Adam7: rows are refined per pass
    if (png_get_bit_depth(png, info) == 16 && std::endian::native == std::endian::little)
        png_set_swap(png);
    png_read_update_info(png, info);
    image.width = static_cast<int>(png_get_image_width(png, info));
    image.height = static_cast<int>(png_get_image_height(png, info));
    image.channels = png_get_channels(png, info);
    image.bitDepth = png_get_bit_depth(png, info);
    const size_t rowBytes = png_get_rowbytes(png, info);
    bytes.resize(rowBytes * static_cast<size_t>(image.height));
    for (int pass = 0; pass < passes; ++pass)
        for (int y = 0; y < image.height; ++y)
            png_read_row(png, bytes.data() + size_t(y) * rowBytes, nullptr);
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace

void writePngRgb8(const std::string& path, int width, int height, int channels,
                  const std::vector<uint8_t>& pixels) {
    if (channels != 3 && channels != 4)
        throw IoError(path + ": cannot write a PNG with " + std::to_string(channels) +
                      " channels (3 or 4)");
    checkSize(path, width, height, channels, pixels.size());
    PngLayout layout{width, height, channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, 8};
    writePng(path, layout, pixels.data(), size_t(width) * size_t(channels));
}

void writePngGray16(const std::string& path, int width, int height,
                    const std::vector<uint16_t>& pixels) {
    checkSize(path, width, height, 1, pixels.size());
    PngLayout layout{width, height, PNG_COLOR_TYPE_GRAY, 16};
    writePng(path, layout, reinterpret_cast<const uint8_t*>(pixels.data()), size_t(width) * 2);
}

PngImage readPng(const std::string& path) {
    FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    png_byte signature[8] = {};
    size_t got = std::fread(signature, 1, sizeof signature, file);
    if (got != sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0) {
        std::fclose(file);
        throw FormatError(path + ": not a PNG file");
    }
    std::rewind(file);
    PngImage image;
    std::vector<uint8_t> bytes;
    PngStatus status;
    bool ok = decodePng(file, image, bytes, status);
    std::fclose(file);
    if (!ok) throw FormatError(path + ": cannot read PNG (" + status.message + ")");

    const size_t count = size_t(image.width) * size_t(image.height) * size_t(image.channels);
    image.samples.resize(count);
    if (image.bitDepth == 16) std::memcpy(image.samples.data(), bytes.data(), count * 2);
    else
        for (size_t i = 0; i < count; ++i) image.samples[i] = bytes[i];
    return image;
}

}  // namespace flowsurf::io
