#include "io/temp_file.h"

#include "core/errors.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace flowsurf::io::detail {

namespace {
std::atomic<unsigned> gTempCounter{0};
}

std::string writeErrorMessage(const std::string& path, int err) {
    namespace fs = std::filesystem;
    if (err == ENOENT) {
        fs::path folder = fs::path(path).parent_path();
        std::error_code ec;
        if (!folder.empty() && !fs::is_directory(folder, ec))
            return path + ": cannot write (folder " + folder.string() + " does not exist)";
    }
    return path + ": cannot write (" + std::system_category().message(err) + ")";
}

TempFile::TempFile(const std::string& finalPath, const std::string& suffix)
    : finalPath_(finalPath) {
    // O_EXCL with our own unique name rather than mkstemp: mkstemp creates mode 0600,
    // and the output should get the usual permissions.
    for (int attempt = 0; attempt < 100; ++attempt) {
        tmpPath_ = finalPath + ".tmp-" + std::to_string(::getpid()) + "-" +
                   std::to_string(gTempCounter++) + suffix;
        fd_ = ::open(tmpPath_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd_ >= 0) return;
        if (errno != EEXIST) throw IoError(writeErrorMessage(finalPath, errno));
    }
    throw IoError(finalPath + ": cannot write (no free temporary file name)");
}

TempFile::~TempFile() { discard(); }

void TempFile::discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!done_) ::unlink(tmpPath_.c_str());
    done_ = true;
}

std::string TempFile::release() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    done_ = true;
    return tmpPath_;
}

void TempFile::commit() {
    if (fd_ >= 0) {
        int rc = ::close(fd_);
        fd_ = -1;
        if (rc != 0) {
            int err = errno;
            discard();
            throw IoError(writeErrorMessage(finalPath_, err));
        }
    }
    if (done_) throw IoError(finalPath_ + ": cannot write (temporary file already removed)");
    if (std::rename(tmpPath_.c_str(), finalPath_.c_str()) != 0) {
        int err = errno;
        discard();
        throw IoError(finalPath_ + ": cannot rename the temporary file into place (" +
                      std::system_category().message(err) + ")");
    }
    done_ = true;
}

}  // namespace flowsurf::io::detail
