// PNG round trips and the ffmpeg video writer; failed writes leave no file behind.
#include "core/errors.h"
#include "io/image_writer.h"
#include "io/video_writer.h"

#include "test_io_common.h"

#include <unistd.h>

#include <cstdlib>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

bool haveFfmpeg() { return std::system("ffmpeg -version > /dev/null 2>&1") == 0; }

// A frame whose pixels encode their position, so rows cannot be silently swapped.
std::vector<uint8_t> gradient(int width, int height, int channels, int frame = 0) {
    std::vector<uint8_t> px(size_t(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                px[(size_t(y) * width + x) * channels + c] = uint8_t(x * 7 + y * 13 + c * 50 + frame * 20);
    return px;
}

// Sets PATH for one scope (to hide ffmpeg or put a fake one first).
class ScopedPath {
public:
    explicit ScopedPath(const std::string& path) {
        const char* old = std::getenv("PATH");
        saved_ = old ? old : "";
        ::setenv("PATH", path.c_str(), 1);
    }
    ~ScopedPath() { ::setenv("PATH", saved_.c_str(), 1); }

private:
    std::string saved_;
};

}  // namespace

TEST(IoImages, PngRoundTripRgb8AndRgba8) {
    ScratchDir dir;
    for (int channels : {3, 4}) {
        const std::string path = dir.file("c" + std::to_string(channels) + ".png");
        const auto pixels = gradient(17, 9, channels);
        io::writePngRgb8(path, 17, 9, channels, pixels);
        io::PngImage img = io::readPng(path);
        EXPECT_EQ(img.width, 17);
        EXPECT_EQ(img.height, 9);
        EXPECT_EQ(img.channels, channels);
        EXPECT_EQ(img.bitDepth, 8);
        EXPECT_EQ(img.samples, std::vector<uint16_t>(pixels.begin(), pixels.end()));
    }
    EXPECT_EQ(dir.list(), (std::vector<std::string>{"c3.png", "c4.png"}));  // no temporaries
}

TEST(IoImages, PngRoundTripGray16) {
    ScratchDir dir;
    std::vector<uint16_t> pixels(5 * 4);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint16_t(i * 3277 + 1);  // high and low bytes
    io::writePngGray16(dir.file("g.png"), 5, 4, pixels);
    io::PngImage img = io::readPng(dir.file("g.png"));
    EXPECT_EQ(img.channels, 1);
    EXPECT_EQ(img.bitDepth, 16);
    EXPECT_EQ(img.samples, pixels);
}

TEST(IoImages, PngOverwritesExistingFile) {
    ScratchDir dir;
    writeText(dir.file("x.png"), "old");
    io::writePngRgb8(dir.file("x.png"), 2, 2, 3, gradient(2, 2, 3));
    EXPECT_EQ(io::readPng(dir.file("x.png")).width, 2);
}

TEST(IoImages, PngIntoMissingFolderThrowsAndLeavesNothing) {
    ScratchDir dir;
    const std::string path = dir.file("no/such/folder/x.png");
    try {
        io::writePngRgb8(path, 2, 2, 3, gradient(2, 2, 3));
        ADD_FAILURE() << "no exception";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(dir.list().empty());
}

TEST(IoImages, PngWrongSizeThrowsAndLeavesNothing) {
    ScratchDir dir;
    EXPECT_THROW(io::writePngRgb8(dir.file("x.png"), 4, 4, 3, gradient(2, 2, 3)), IoError);
    EXPECT_THROW(io::writePngRgb8(dir.file("x.png"), 2, 2, 2, gradient(2, 2, 2)), IoError);
    EXPECT_THROW(io::writePngGray16(dir.file("x.png"), 0, 0, {}), IoError);
    EXPECT_TRUE(dir.list().empty());
}

TEST(IoImages, ReadPngErrors) {
    ScratchDir dir;
    EXPECT_THROW(io::readPng(dir.file("missing.png")), IoError);
    writeText(dir.file("text.png"), "not a png at all");
    EXPECT_THROW(io::readPng(dir.file("text.png")), FormatError);
    io::writePngRgb8(dir.file("ok.png"), 8, 8, 3, gradient(8, 8, 3));
    writeText(dir.file("cut.png"), readBytes(dir.file("ok.png")).substr(0, 60));
    EXPECT_THROW(io::readPng(dir.file("cut.png")), FormatError);
}

TEST(IoVideo, WritesSmallMp4WithOddSize) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg not installed";
    ScratchDir dir;
    {
        io::VideoWriter video(dir.file("clip.mp4"), 33, 17, {10, 23});  // odd: padded to 34x18
        for (int f = 0; f < 3; ++f) video.addFrame(gradient(33, 17, 3, f));
        video.finish();
    }
    EXPECT_EQ(dir.list(), (std::vector<std::string>{"clip.mp4"}));
    const std::string bytes = readBytes(dir.file("clip.mp4"));
    ASSERT_GT(bytes.size(), 100u);
    EXPECT_EQ(bytes.substr(4, 4), "ftyp");  // an MP4 container
}

TEST(IoVideo, UnfinishedWriterLeavesNoFile) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg not installed";
    ScratchDir dir;
    {
        io::VideoWriter video(dir.file("clip.mp4"), 16, 16);
        video.addFrame(gradient(16, 16, 3));
        // destroyed without finish(): a render that failed mid-way
    }
    EXPECT_TRUE(dir.list().empty());
}

TEST(IoVideo, BadFrameAndFolderAreIoErrors) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg not installed";
    ScratchDir dir;
    EXPECT_THROW(io::VideoWriter(dir.file("no/folder/clip.mp4"), 16, 16), IoError);
    EXPECT_THROW(io::VideoWriter(dir.file("zero.mp4"), 0, 16), IoError);
    {
        io::VideoWriter video(dir.file("clip.mp4"), 16, 16);
        EXPECT_THROW(video.addFrame(gradient(8, 8, 3)), IoError);
        EXPECT_THROW(io::VideoWriter(dir.file("clip2.mp4"), 16, 16).finish(), IoError);  // no frames
    }
    EXPECT_TRUE(dir.list().empty());
}

TEST(IoVideo, MissingFfmpegIsClearIoError) {
    ScratchDir dir;
    ScopedPath path(dir.path().string());  // a folder without ffmpeg
    try {
        io::VideoWriter video(dir.file("clip.mp4"), 16, 16);
        ADD_FAILURE() << "no exception";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("ffmpeg not found: install the Debian package ffmpeg"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(dir.list().empty());
}

TEST(IoVideo, FfmpegDyingIsIoErrorNotSigpipe) {
    ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "bin");
    writeText(dir.file("bin/ffmpeg"), "#!/bin/sh\necho 'boom: fake encoder failure' >&2\nexit 3\n");
    std::filesystem::permissions(dir.file("bin/ffmpeg"), std::filesystem::perms::owner_all);
    ScopedPath path(dir.file("bin") + ":/usr/bin:/bin");
    std::string message;
    try {
        // More than a pipe buffer of frames: writes hit the closed pipe (EPIPE, SIGPIPE).
        io::VideoWriter video(dir.file("clip.mp4"), 64, 64);
        for (int f = 0; f < 100; ++f) video.addFrame(gradient(64, 64, 3, f));
        video.finish();
    } catch (const IoError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("clip.mp4"), std::string::npos) << message;
    EXPECT_NE(message.find("boom: fake encoder failure"), std::string::npos) << message;
    EXPECT_EQ(dir.list(), std::vector<std::string>{"bin"});
}
