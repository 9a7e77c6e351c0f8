// flowsurf — files are read in a child process (private to src/io). VTK's readers (and
// our PLY/OBJ parsers) run in `flowsurf-reader`, started with posix_spawn (never fork:
// the step prefetch thread makes it unsafe) with only its socket and reasons pipe open,
// inside a sandbox (reader/sandbox.h) and, per request, budgets that grow with the input
// (readerBudget): a wall-clock deadline kept here, CPU time and address space limited in
// the child. The surface comes back over the socket (reader/reader_wire.h). A crash, abort, hang,
// allocation bomb or refused system call ends the child and becomes a one-line FormatError
// naming the file and what was hit. One ReaderProcess serves many requests (a time series
// keeps its child alive); a request below another folder gets a fresh child confined to
// that folder. The limits and the environment variables that set them, the executable
// (FLOWSURF_READER) and FLOWSURF_READER_SANDBOX=off: doc/reader_sandbox.md.
#pragma once

#include "core/mesh.h"
#include "io/dataset_reader.h"
#include "io/reader/reader_wire.h"

#include <sys/types.h>

#include <mutex>
#include <string>
#include <vector>

namespace flowsurf::io::detail {

// What one request on an input of `inputBytes` may use (doc/reader_sandbox.md has the
// table). The wall clock (kept by the library) is kReaderBaseS, for starting the child and
// a small file on a busy machine, plus kReaderSecondsPerMb per MiB: 4x what the slowest
// reader measured needs (legacy ASCII .vtk, 70 MB in 9 s on a loaded 2-core machine). CPU
// time: a second (the child rounds what it used so far up to whole seconds, so a small file
// that spins a reader is stopped within two seconds) plus twice the wall clock's allowance
// per MiB (VTK's filters run on several threads). Address space: kReaderMemoryBaseMb (the
// libraries, thread stacks and arenas; a small file needs under 400) plus
// kReaderMemoryPerMb per MiB, at most the hard limit (3/4 of physical memory). Times are
// capped at a week (an unbounded folder).
struct ReaderBudget {
    long long wallS = 0;
    long long cpuS = 0;
    unsigned long long memoryMb = 0;
};
constexpr long long kReaderBaseS = 30;
constexpr double kReaderSecondsPerMb = 0.5;
constexpr long long kReaderCpuBaseS = 1;
constexpr double kReaderCpuSecondsPerMb = 1.0;
constexpr unsigned long long kReaderMemoryBaseMb = 2048;
constexpr unsigned long long kReaderMemoryPerMb = 32;
ReaderBudget readerBudget(unsigned long long inputBytes);

class ReaderProcess {
public:
    ReaderProcess();  // finds the executable (IoError if nowhere); the child starts with a request
    ~ReaderProcess();
    ReaderProcess(const ReaderProcess&) = delete;
    ReaderProcess& operator=(const ReaderProcess&) = delete;

    // Every time step of `path` (at most `maxSteps`, 0 = all): opened, then read step by step.
    core::Dataset readDataset(const std::string& path, size_t maxSteps);
    // Opens `path` as the child's current multi-step source: its format and times.
    // `options`: OpenFOAM's boundary patches and case layout.
    using SourceInfo = wire::SourceInfo;
    SourceInfo open(const std::string& path, const SourceOptions& options = {});
    // Step `index` of the source opened last; `label` names it in errors.
    core::SurfaceMesh readStep(size_t index, const std::string& label);
    FileInfo inspect(const std::string& path, const SourceOptions& options = {});

private:
    // Sends `request` with `budget`, then reads a Reply; a typed error from the child is
    // rethrown, a dead or hung child becomes a FormatError naming `label`.
    template <typename Reply>
    Reply call(const std::string& label, const ReaderBudget& budget, wire::Request request);
    // A running child confined to `root` (a running one elsewhere is ended first).
    void ensureChild(const std::string& root);
    void spawn(const std::string& root);
    // Ends the child (killing it if needed); how it ended goes to lastStatus_ and lastReason_.
    void reap(bool kill);

    std::recursive_mutex mutex_;  // the prefetch thread and the caller share a child
    std::string exe_;
    pid_t pid_ = -1;
    int fd_ = -1, reasonFd_ = -1;  // the socket; the reasons pipe's read end
    std::string root_;             // the folder the running child may read below
    int lastStatus_ = 0;           // how the last child ended, and what it said (reasons pipe)
    std::string lastReason_;
    unsigned long long memoryHardMb_ = 0;
    ReaderBudget openBudget_;  // of the source opened last, for its step requests
    wire::Request lastOpen_;   // re-opened after a restart (none: op Quit)
};

// What a request on `path` may read: the file's size, and for formats whose file names
// others (.case, .pvd, an OpenFOAM case's .foam) everything in its folder and below.
unsigned long long readerInputBytes(const std::string& path);

}  // namespace flowsurf::io::detail
