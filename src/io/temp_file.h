// flowsurf — write-then-rename output files (private to src/io). The temporary sits in
// the destination folder so that the final rename is atomic: a reader of `path` sees
// either the old file or the complete new one, never a partial write.
#pragma once

#include <string>

namespace flowsurf::io::detail {

class TempFile {
public:
    // Creates "PATH.tmp-PID-N" + `suffix` exclusively (mode 0666 less the umask).
    // Throws IoError naming `finalPath` and the reason (e.g. the folder does not exist).
    explicit TempFile(const std::string& finalPath, const std::string& suffix = "");
    // Removes the temporary unless commit() succeeded.
    ~TempFile();
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    const std::string& path() const { return tmpPath_; }
    const std::string& finalPath() const { return finalPath_; }
    // The descriptor from creation; the caller may take it over (then set it to -1).
    int& fd() { return fd_; }

    // Renames the temporary to the final path. Throws IoError.
    void commit();
    // Closes the descriptor and hands the file over: the caller removes it from now on.
    std::string release();
    // Removes the temporary now (idempotent).
    void discard();

private:
    std::string finalPath_, tmpPath_;
    int fd_ = -1;
    bool done_ = false;
};

// "PATH: cannot write (REASON)" with a clearer reason for a missing folder.
std::string writeErrorMessage(const std::string& path, int err);

}  // namespace flowsurf::io::detail
