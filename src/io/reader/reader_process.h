// flowsurf — files are read in a child process (private to src/io). VTK's readers (and
// our PLY/OBJ parsers) run in `flowsurf-reader`, started with posix_spawn (never fork:
// the step prefetch thread makes it unsafe) under RLIMIT_AS and, per request, a time
// budget that grows with the input (readerBudgetSeconds: wall clock here, CPU time in the
// child); the surface comes back over a socket. A crash, abort, hang or allocation bomb
// ends the child and becomes a one-line FormatError naming the file. One ReaderProcess
// serves many requests: a time series keeps its child alive.
//
// Environment: FLOWSURF_READER (the executable; default: next to the library or program, in
// its ../libexec/flowsurf/ (core/program_dirs.h), else the build tree's),
// FLOWSURF_READER_MEMORY_MB (address space, default 3/4 of physical memory),
// FLOWSURF_READER_TIMEOUT_S (a fixed budget in seconds per request instead of the
// size-based one).
#pragma once

#include "core/mesh.h"
#include "io/dataset_reader.h"

#include <sys/types.h>

#include <mutex>
#include <string>
#include <vector>

namespace flowsurf::io::detail {

class ReaderProcess {
public:
    ReaderProcess();  // spawns the child; throws IoError if it cannot be started
    ~ReaderProcess();
    ReaderProcess(const ReaderProcess&) = delete;
    ReaderProcess& operator=(const ReaderProcess&) = delete;

    // Every time step of `path` (at most `maxSteps`, 0 = all).
    core::Dataset readDataset(const std::string& path, size_t maxSteps);
    // Opens `path` as the child's current multi-step source: its format and times.
    // `options`: OpenFOAM's boundary patches and case layout.
    struct SourceInfo {
        std::string format;
        std::vector<double> times;
    };
    SourceInfo open(const std::string& path, const SourceOptions& options = {});
    // Step `index` of the source opened last; `label` names it in errors.
    core::SurfaceMesh readStep(size_t index, const std::string& label);
    FileInfo inspect(const std::string& path, const SourceOptions& options = {});

private:
    // Sends a request, then parses the reply with `parse` (called with a wire::Reader
    // after an Ok status); a typed error from the child is rethrown, a dead or hung
    // child becomes a FormatError naming `label`.
    template <typename Send, typename Parse>
    auto call(const std::string& label, long long budgetS, Send send, Parse parse);
    void spawn();
    SourceInfo openLocked(const std::string& path, const SourceOptions& options);
    // Ends the child (killing it if needed) and returns why it died, for messages.
    std::string reap(bool kill);

    std::mutex mutex_;  // the prefetch thread and the caller share a child
    pid_t pid_ = -1;
    int fd_ = -1;
    long long openBudgetS_ = 0;  // of the source opened last, for its step requests
    unsigned long long memoryMb_ = 0;
    std::string lastOpen_;  // re-opened after a restart, with these options
    SourceOptions lastOptions_;
};

// The time one request may take on an input of `inputBytes`: kReaderBaseS (starting the
// child, a small file on a busy machine) plus kReaderSecondsPerMb per MiB. The slowest
// reader measured (legacy ASCII .vtk, 70 MB in 9 s on a loaded 2-core machine: 8 MB/s;
// ASCII EnSight 23 MB/s) is 4x faster than this allows, so a real 1 GiB case reads
// (budget 30 + 512 s), while a small file that hangs a reader is stopped after 30 s
// instead of the former fixed 300 s. Capped at a week (an unbounded folder).
constexpr long long kReaderBaseS = 30;
constexpr double kReaderSecondsPerMb = 0.5;
long long readerBudgetSeconds(unsigned long long inputBytes);
// What a request on `path` may read: the file's size, and for formats whose file names
// others (.case, .pvd, an OpenFOAM case's .foam) everything in its folder and below.
unsigned long long readerInputBytes(const std::string& path);

// Where flowsurf-reader is (see above); throws IoError if nowhere.
std::string readerExecutable();

}  // namespace flowsurf::io::detail
