#include "io/reader_process.h"

#include "core/errors.h"
#include "core/program_dirs.h"
#include "io/reader/reader_wire.h"
#include "io/reader/sandbox.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

long envNumber(const char* name, long fallback) {
    const char* v = std::getenv(name);
    if (!v || !*v) return fallback;
    char* end = nullptr;
    long n = std::strtol(v, &end, 10);
    return end && *end == '\0' && n > 0 ? n : fallback;
}

unsigned long long defaultMemoryMb() {
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || size <= 0) return 8192;
    return std::max<unsigned long long>(2048, (unsigned long long)pages * size / 4 * 3 >> 20);
}

// FLOWSURF_READER_TIMEOUT_S and FLOWSURF_READER_MEMORY_MB, or 0 when unset.
long long fixedSeconds() { return envNumber("FLOWSURF_READER_TIMEOUT_S", 0); }
unsigned long long fixedMemoryMb() { return (unsigned long long)envNumber("FLOWSURF_READER_MEMORY_MB", 0); }

// The budgets for `path`: its input's size, or the environment's fixed values.
ReaderBudget budgetFor(const std::string& path) {
    ReaderBudget b = readerBudget(readerInputBytes(path));
    if (const long long s = fixedSeconds(); s > 0) b.wallS = b.cpuS = s;
    if (const unsigned long long mb = fixedMemoryMb(); mb > 0) b.memoryMb = mb;
    if (sandbox::kSanitized) b.memoryMb = 0;  // an address-space limit breaks AddressSanitizer's shadow memory
    return b;
}

// Which variable sets another time budget, for messages.
std::string timeoutHint() {
    return fixedSeconds() > 0 ? "FLOWSURF_READER_TIMEOUT_S"
                              : "its limit for this input's size; FLOWSURF_READER_TIMEOUT_S sets another";
}

// Why the child ended, from its exit status and what it wrote to the reasons pipe.
std::string deathText(int status, const std::string& reason, const ReaderBudget& budget) {
    if (WIFSIGNALED(status)) {
        switch (const int sig = WTERMSIG(status)) {
            case SIGSYS:
                return "was stopped by its sandbox: it " + (reason.empty() ? "made a forbidden system call" : reason);
            case SIGXCPU:
                return "used more than " + std::to_string(budget.cpuS) + " s of CPU (" + timeoutHint() + ")";
            case SIGSEGV:
            case SIGBUS:
            case SIGFPE:
            case SIGILL: return std::string("crashed (SIG") + sigabbrev_np(sig) + ")";
            case SIGABRT: return "aborted (SIGABRT)";
            default: return "was killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
        }
    }
    if (WIFEXITED(status))
        return "exited unexpectedly (status " + std::to_string(WEXITSTATUS(status)) + ")" +
               (reason.empty() ? "" : ": " + reason);
    return "stopped";
}

// The folder a request on `path` reads below (symbolic links resolved, as the kernel sees it).
std::string rootFor(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) p = fs::absolute(path);
    return p.has_parent_path() ? p.parent_path().string() : "/";
}

bool isBelow(const std::string& path, const std::string& root) {
    const fs::path rel = fs::path(path).lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

// The reader's warnings that end every reply, printed as the library's own.
void printWarnings(wire::Reader& r) {
    for (const auto& text : r.get<std::vector<std::string>>())
        std::fprintf(stderr, "flowsurf: warning: %s\n", text.c_str());
}

// Where flowsurf-reader is (reader_process.h); throws IoError if nowhere.
std::string readerExecutable() {
    if (const char* env = std::getenv("FLOWSURF_READER"); env && *env) return env;
    // Next to the binary or library this code is linked into, or in ../libexec/flowsurf/.
    for (const fs::path& dir : core::programDirs())
        for (const fs::path& p : {dir / "flowsurf-reader", dir.parent_path() / "libexec/flowsurf/flowsurf-reader"})
            if (access(p.c_str(), X_OK) == 0) return p.string();
#ifdef FLOWSURF_READER_BUILD_PATH
    if (access(FLOWSURF_READER_BUILD_PATH, X_OK) == 0) return FLOWSURF_READER_BUILD_PATH;
#endif
    throw IoError("cannot find flowsurf-reader (the process files are read in); set FLOWSURF_READER");
}

}  // namespace

ReaderBudget readerBudget(unsigned long long inputBytes) {
    constexpr double kWeek = 7 * 24 * 3600;
    const double mb = double(inputBytes) / double(1 << 20);
    ReaderBudget b;
    b.wallS = (long long)std::min(kWeek, double(kReaderBaseS) + std::ceil(mb * kReaderSecondsPerMb));
    b.cpuS = (long long)std::min(kWeek, std::round(double(kReaderCpuBaseS) + mb * kReaderCpuSecondsPerMb));
    const double memory = double(kReaderMemoryBaseMb) + std::ceil(mb) * double(kReaderMemoryPerMb);
    b.memoryMb = memory >= double(1ull << 40) ? 1ull << 40 : (unsigned long long)memory;
    return b;
}

unsigned long long readerInputBytes(const std::string& path) {
    std::error_code ec;
    const fs::path p(path);
    unsigned long long bytes = fs::is_regular_file(p, ec) ? fs::file_size(p, ec) : 0;
    if (ec) bytes = 0;
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".case" && ext != ".pvd" && ext != ".foam") return bytes;
    // Every file in the folder and below (the step files, processor*/ of a decomposed
    // case); a folder too large to list counts as unbounded.
    constexpr size_t kMaxEntries = 200000;
    size_t entries = 0;
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
        if (++entries > kMaxEntries) return ~0ull;
        std::error_code sizeEc;
        if (it->is_regular_file(sizeEc) && it->path() != p) {
            const auto size = it->file_size(sizeEc);
            if (!sizeEc) bytes += size;
        }
    }
    return bytes;
}

ReaderProcess::ReaderProcess()
    : exe_(readerExecutable()), memoryHardMb_(fixedMemoryMb() > 0 ? fixedMemoryMb() : defaultMemoryMb()) {
    if (sandbox::kSanitized) memoryHardMb_ = 0;
}

ReaderProcess::~ReaderProcess() {
    if (pid_ <= 0) return;
    wire::Writer w(fd_);
    const wire::Request quit;
    wire::record(w, quit);
    w.flush();
    reap(false);
}

void ReaderProcess::ensureChild(const std::string& root) {
    if (pid_ > 0 && isBelow(root, root_)) return;
    if (pid_ > 0) reap(true);  // confined below another folder
    spawn(root);
}

void ReaderProcess::spawn(const std::string& root) {
    int sv[2] = {-1, -1}, reasons[2] = {-1, -1};
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0 || pipe2(reasons, O_CLOEXEC) != 0) {
        const int error = errno;
        for (int fd : {sv[0], sv[1]})
            if (fd >= 0) close(fd);
        throw IoError(std::string("cannot start the reader process: ") + std::strerror(error));
    }
    fcntl(reasons[0], F_SETFL, O_NONBLOCK);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // dup2 clears close-on-exec; then nothing else of ours reaches the child.
    posix_spawn_file_actions_adddup2(&actions, sv[1], sandbox::kSocketFd);
    posix_spawn_file_actions_adddup2(&actions, reasons[1], sandbox::kReasonFd);
    posix_spawn_file_actions_addclosefrom_np(&actions, sandbox::kReasonFd + 1);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    // VTK's own printing is trapped in the child; what escapes (a crash's last words) is noise.
    if (!std::getenv("FLOWSURF_READER_STDERR")) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const std::string mem = std::to_string(memoryHardMb_);
    std::vector<char*> argv{const_cast<char*>(exe_.c_str()), const_cast<char*>("--memory-mb"),
                            const_cast<char*>(mem.c_str()),  const_cast<char*>("--root"),
                            const_cast<char*>(root.c_str()), nullptr};
    pid_t pid = -1;
    int rc = posix_spawn(&pid, exe_.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(sv[1]);
    close(reasons[1]);
    if (rc != 0) {
        close(sv[0]);
        close(reasons[0]);
        throw IoError("cannot start the reader process " + exe_ + ": " + std::strerror(rc));
    }
    pid_ = pid;
    fd_ = sv[0];
    reasonFd_ = reasons[0];
    root_ = root;
    lastStatus_ = 0;
}

void ReaderProcess::reap(bool kill) {
    if (pid_ <= 0) return;
    if (kill) ::kill(pid_, SIGKILL);
    close(fd_);  // a child blocked on the socket sees the end of the stream
    fd_ = -1;
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    char text[512];
    const ssize_t n = read(reasonFd_, text, sizeof text);
    close(reasonFd_);
    reasonFd_ = -1;
    lastStatus_ = status;
    lastReason_.assign(text, n > 0 ? size_t(n) : 0);
}

template <typename Reply>
Reply ReaderProcess::call(const std::string& label, const ReaderBudget& budget, wire::Request request) {
    request.cpuSeconds = uint64_t(budget.cpuS);
    request.memoryMb = budget.memoryMb;
    wire::Writer w(fd_);
    wire::record(w, request);
    wire::Reader r(fd_, wire::Reader::Clock::now() + std::chrono::seconds(budget.wallS));
    try {
        if (!w.flush()) throw wire::Broken{};
        const auto status = r.get<wire::Status>();
        if (status != wire::Status::Ok) {
            const auto what = r.get<std::string>();
            printWarnings(r);
            switch (status) {
                case wire::Status::IoError: throw IoError(what);
                case wire::Status::FormatError: throw FormatError(what);
                case wire::Status::FieldError: throw FieldError(what);
                case wire::Status::ConfigError: throw ConfigError(what);
                default: throw FormatError(label + ": " + what);
            }
        }
        Reply reply;
        wire::record(r, reply);
        printWarnings(r);
        return reply;
    } catch (const wire::Broken& b) {
        // Killed on a timeout; otherwise the child died or spoke nonsense: stop it either way.
        reap(true);
        const std::string why = b.timedOut
                                    ? "took longer than " + std::to_string(budget.wallS) + " s (" + timeoutHint() + ")"
                                    : deathText(lastStatus_, lastReason_, budget);
        throw FormatError(label + ": the reader " + why + "; the file is malformed or not supported");
    }
}

core::Dataset ReaderProcess::readDataset(const std::string& path, size_t maxSteps) {
    std::lock_guard lock(mutex_);
    const SourceInfo info = open(path, {});
    const size_t steps = info.times.empty() ? 1 : info.times.size();
    core::Dataset dataset;
    dataset.source = path;
    for (size_t i = 0; i < (maxSteps > 0 ? std::min(steps, maxSteps) : steps); ++i) {
        const double t = info.times.empty() ? 0.0 : info.times[i];
        dataset.steps.push_back({t, readStep(i, wire::stepLabel(path, info.times, i))});
    }
    return dataset;
}

ReaderProcess::SourceInfo ReaderProcess::open(const std::string& path, const SourceOptions& options) {
    std::lock_guard lock(mutex_);
    ensureChild(rootFor(path));
    openBudget_ = budgetFor(path);
    lastOpen_ = {};  // the child drops its source before opening another
    const wire::Request request{wire::Op::Open, path, options, 0, 0, 0};
    const auto info = call<SourceInfo>(path, openBudget_, request);
    lastOpen_ = request;
    return info;
}

core::SurfaceMesh ReaderProcess::readStep(size_t index, const std::string& label) {
    std::lock_guard lock(mutex_);
    if (pid_ <= 0 && lastOpen_.op == wire::Op::Open) {  // the child died: restore its source
        const wire::Request again = lastOpen_;
        open(again.path, again.options);
    }
    ensureChild(root_);
    return call<core::SurfaceMesh>(label, openBudget_, {wire::Op::Step, {}, {}, index, 0, 0});
}

FileInfo ReaderProcess::inspect(const std::string& path, const SourceOptions& options) {
    std::lock_guard lock(mutex_);
    ensureChild(rootFor(path));
    return call<FileInfo>(path, budgetFor(path), {wire::Op::Inspect, path, options, 0, 0, 0});
}

}  // namespace flowsurf::io::detail
