// H.264 MP4 through the ffmpeg program: raw RGB frames go down a popen() pipe, ffmpeg's
// messages go to a log next to the temporary video so that failures can quote them.
// Writes happen with SIGPIPE blocked for this thread (a dead ffmpeg must give an
// error, not kill the process) without touching the process-wide signal disposition.
#include "io/video_writer.h"

#include "core/errors.h"
#include "io/temp_file.h"

#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

namespace flowsurf::io {

namespace {

// Blocks SIGPIPE in this thread for a scope and swallows one raised inside it.
class SigpipeGuard {
public:
    SigpipeGuard() {
        sigemptyset(&pipeSet_);
        sigaddset(&pipeSet_, SIGPIPE);
        sigset_t pending;
        sigpending(&pending);
        wasPending_ = sigismember(&pending, SIGPIPE) == 1;
        pthread_sigmask(SIG_BLOCK, &pipeSet_, &oldMask_);
    }
    ~SigpipeGuard() {
        if (!wasPending_) {
            const timespec zero{0, 0};
            while (sigtimedwait(&pipeSet_, nullptr, &zero) == -1 && errno == EINTR) {
            }
        }
        pthread_sigmask(SIG_SETMASK, &oldMask_, nullptr);
    }

private:
    sigset_t pipeSet_, oldMask_;
    bool wasPending_ = false;
};

std::string findProgram(const std::string& name) {
    const char* env = std::getenv("PATH");
    std::stringstream dirs(env && *env ? env : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string logPathFor(const std::string& tmpPath) { return tmpPath + ".log"; }

// ffmpeg's own words, for the exception; one line.
std::string ffmpegLog(const std::string& tmpPath) {
    std::ifstream in(logPathFor(tmpPath));
    std::string text, line;
    while (std::getline(in, line))
        if (!line.empty()) text += (text.empty() ? "" : "; ") + line;
    if (text.size() > 600) text = text.substr(0, 600) + "...";
    return text.empty() ? std::string("no message") : text;
}

std::string exitText(int status) {
    if (status == -1) return "could not wait for ffmpeg";
    if (WIFEXITED(status)) return "ffmpeg exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
    return "ffmpeg ended abnormally";
}

}  // namespace

VideoWriter::VideoWriter(const std::string& path, int width, int height, const VideoOptions& options)
    : path_(path), width_(width), height_(height) {
    if (width <= 0 || height <= 0)
        throw IoError(path + ": cannot encode a " + std::to_string(width) + "x" +
                      std::to_string(height) + " video");
    if (options.fps <= 0 || options.crf < 0 || options.crf > 51)
        throw IoError(path + ": cannot encode with fps " + std::to_string(options.fps) +
                      " and crf " + std::to_string(options.crf) + " (fps > 0, crf 0..51)");
    const std::string ffmpeg = findProgram("ffmpeg");
    if (ffmpeg.empty())
        throw IoError(path + ": ffmpeg not found: install the Debian package ffmpeg (MP4 output runs the "
                      "ffmpeg program found on PATH), or write PNG frames (a path with %04d)");

    // Reserve the temporary name (also checks that the folder is writable).
    tmpPath_ = detail::TempFile(path, ".mp4").release();

    std::ostringstream cmd;
    cmd << shellQuote(ffmpeg) << " -hide_banner -loglevel error -f rawvideo -pix_fmt rgb24 -s "
        << width << "x" << height << " -r " << options.fps << " -i -";
    // yuv420p needs even sizes: pad by one pixel rather than refuse the size.
    if (width % 2 || height % 2) cmd << " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'";
    cmd << " -c:v libx264 -pix_fmt yuv420p -crf " << options.crf
        << " -movflags +faststart -f mp4 -y " << shellQuote(tmpPath_) << " 2> "
        << shellQuote(logPathFor(tmpPath_));
    // "e": close-on-exec, so other children never hold the pipe open.
    pipe_ = ::popen(cmd.str().c_str(), "we");
    if (!pipe_) {
        int err = errno;
        ::unlink(tmpPath_.c_str());
        throw IoError(path + ": cannot start ffmpeg (" + std::system_category().message(err) + ")");
    }
}

VideoWriter::~VideoWriter() {
    if (pipe_) {
        // Closing stdin ends ffmpeg; what it wrote is then removed.
        SigpipeGuard guard;
        ::pclose(pipe_);
        pipe_ = nullptr;
    }
    if (!tmpPath_.empty()) {
        ::unlink(tmpPath_.c_str());
        ::unlink(logPathFor(tmpPath_).c_str());
    }
}

void VideoWriter::addFrame(const std::vector<uint8_t>& rgb) {
    if (!pipe_) throw IoError(path_ + ": the video is already finished or failed");
    const size_t expected = size_t(width_) * size_t(height_) * 3;
    if (rgb.size() != expected)
        throw IoError(path_ + ": frame " + std::to_string(frames_) + " has " +
                      std::to_string(rgb.size()) + " bytes, expected " + std::to_string(expected));
    size_t written;
    {
        SigpipeGuard guard;
        written = std::fwrite(rgb.data(), 1, rgb.size(), pipe_);
    }
    if (written != rgb.size()) {
        // ffmpeg has gone (bad option, disk full...): collect its status and message.
        int status;
        {
            SigpipeGuard guard;
            status = ::pclose(pipe_);
        }
        pipe_ = nullptr;
        std::string message = path_ + ": ffmpeg stopped accepting frames at frame " +
                              std::to_string(frames_) + " (" + exitText(status) + ": " +
                              ffmpegLog(tmpPath_) + ")";
        throw IoError(message);
    }
    ++frames_;
}

void VideoWriter::finish() {
    if (!pipe_) throw IoError(path_ + ": the video is already finished or failed");
    if (frames_ == 0) throw IoError(path_ + ": no frames were added");
    int status;
    {
        SigpipeGuard guard;
        std::fflush(pipe_);
        status = ::pclose(pipe_);
    }
    pipe_ = nullptr;
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw IoError(path_ + ": cannot encode the video (" + exitText(status) + ": " +
                      ffmpegLog(tmpPath_) + ")");
    ::unlink(logPathFor(tmpPath_).c_str());
    if (std::rename(tmpPath_.c_str(), path_.c_str()) != 0)
        throw IoError(path_ + ": cannot rename the temporary video into place (" +
                      std::system_category().message(errno) + ")");
    tmpPath_.clear();
}

}  // namespace flowsurf::io
