#include "io/reader/reader_process.h"

#include "core/errors.h"
#include "core/program_dirs.h"
#include "io/reader/reader_wire.h"

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

bool sanitized() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}

std::string signalText(int sig) {
    switch (sig) {
        case SIGSEGV: return "crashed (SIGSEGV)";
        case SIGBUS: return "crashed (SIGBUS)";
        case SIGFPE: return "crashed (SIGFPE)";
        case SIGILL: return "crashed (SIGILL)";
        case SIGABRT: return "aborted (SIGABRT)";
        case SIGXCPU: return "ran out of CPU time (SIGXCPU)";
        default: return std::string("was killed by signal ") + std::to_string(sig) + " (" + strsignal(sig) + ")";
    }
}

// FLOWSURF_READER_TIMEOUT_S, or 0 when unset (the budget follows the input's size).
long long fixedBudgetSeconds() { return envNumber("FLOWSURF_READER_TIMEOUT_S", 0); }

long long budgetFor(const std::string& path) {
    const long long fixed = fixedBudgetSeconds();
    return fixed > 0 ? fixed : readerBudgetSeconds(readerInputBytes(path));
}

// The reader's warnings that end every reply, printed as the library's own.
void printWarnings(wire::Reader& r) {
    for (uint64_t i = 0, n = r.count(1 << 16); i < n; ++i)
        std::fprintf(stderr, "flowsurf: warning: %s\n", r.str().c_str());
}

}  // namespace

long long readerBudgetSeconds(unsigned long long inputBytes) {
    constexpr long long kWeek = 7 * 24 * 3600;
    const double mb = double(inputBytes) / double(1 << 20);
    const double s = double(kReaderBaseS) + std::ceil(mb * kReaderSecondsPerMb);
    return s >= double(kWeek) ? kWeek : (long long)s;
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

ReaderProcess::ReaderProcess()
    : memoryMb_((unsigned long long)envNumber("FLOWSURF_READER_MEMORY_MB", long(defaultMemoryMb()))) {
    // An address-space limit breaks AddressSanitizer's shadow memory.
    if (sanitized()) memoryMb_ = 0;
    spawn();
}

ReaderProcess::~ReaderProcess() {
    if (pid_ <= 0) return;
    wire::Writer w(fd_);
    w.u64(0);
    w.u8(uint8_t(wire::Op::Quit));
    w.flush();
    reap(false);
}

void ReaderProcess::spawn() {
    const std::string exe = readerExecutable();
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
        throw IoError(std::string("cannot start the reader process: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, sv[1], 3);  // dup2 clears close-on-exec
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    // VTK's own printing is trapped in the child; what escapes (a crash's last words) is noise.
    if (!std::getenv("FLOWSURF_READER_STDERR")) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const std::string mem = std::to_string(memoryMb_);
    std::vector<char*> argv{const_cast<char*>(exe.c_str()), const_cast<char*>("--memory-mb"),
                            const_cast<char*>(mem.c_str()), nullptr};
    pid_t pid = -1;
    int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(sv[1]);
    if (rc != 0) {
        close(sv[0]);
        throw IoError("cannot start the reader process " + exe + ": " + std::strerror(rc));
    }
    pid_ = pid;
    fd_ = sv[0];
}

std::string ReaderProcess::reap(bool kill) {
    if (pid_ <= 0) return "is not running";
    if (kill) ::kill(pid_, SIGKILL);
    close(fd_);  // a child blocked on the socket sees the end of the stream
    fd_ = -1;
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (WIFSIGNALED(status)) return signalText(WTERMSIG(status));
    if (WIFEXITED(status)) return "exited unexpectedly (status " + std::to_string(WEXITSTATUS(status)) + ")";
    return "stopped";
}

template <typename Send, typename Parse>
auto ReaderProcess::call(const std::string& label, long long budgetS, Send send, Parse parse) {
    if (pid_ <= 0) {
        spawn();
        if (!lastOpen_.empty()) {  // the previous child died: restore its open source
            const std::string path = lastOpen_;
            lastOpen_.clear();
            openLocked(path, lastOptions_);
        }
    }
    wire::Writer w(fd_);
    w.u64(uint64_t(budgetS));  // the child's CPU-time budget for this request
    send(w);
    const auto deadline = wire::Reader::Clock::now() + std::chrono::seconds(budgetS);
    wire::Reader r(fd_, deadline);
    try {
        if (!w.flush()) throw wire::Broken{};
        auto status = wire::Status(r.u8());
        if (status != wire::Status::Ok) {
            std::string what = r.str();
            printWarnings(r);
            switch (status) {
                case wire::Status::IoError: throw IoError(what);
                case wire::Status::FormatError: throw FormatError(what);
                case wire::Status::FieldError: throw FieldError(what);
                case wire::Status::ConfigError: throw ConfigError(what);
                default: throw FormatError(label + ": " + what);
            }
        }
        auto result = parse(r);
        printWarnings(r);
        return result;
    } catch (const wire::Broken& b) {
        // Killed on a timeout; otherwise the child died or spoke nonsense: stop it either way.
        std::string why = reap(true);
        if (b.timedOut)
            why = "took longer than " + std::to_string(budgetS) + " s (" +
                  (fixedBudgetSeconds() > 0 ? "FLOWSURF_READER_TIMEOUT_S"
                                            : "its budget for this input's size; FLOWSURF_READER_TIMEOUT_S sets another") +
                  ")";
        throw FormatError(label + ": the reader " + why + "; the file is malformed or not supported");
    }
}

core::Dataset ReaderProcess::readDataset(const std::string& path, size_t maxSteps) {
    std::lock_guard lock(mutex_);
    return call(
        path, budgetFor(path),
        [&](wire::Writer& w) {
            w.u8(uint8_t(wire::Op::Dataset));
            w.str(path);
            w.u64(maxSteps);
        },
        [](wire::Reader& r) { return wire::readDataset(r); });
}

ReaderProcess::SourceInfo ReaderProcess::open(const std::string& path, const SourceOptions& options) {
    std::lock_guard lock(mutex_);
    return openLocked(path, options);
}

ReaderProcess::SourceInfo ReaderProcess::openLocked(const std::string& path, const SourceOptions& options) {
    openBudgetS_ = budgetFor(path);
    SourceInfo info = call(
        path, openBudgetS_,
        [&](wire::Writer& w) {
            w.u8(uint8_t(wire::Op::Open));
            w.str(path);
            wire::writeSourceOptions(w, options);
        },
        [](wire::Reader& r) {
            SourceInfo s;
            s.format = r.str();
            s.times.resize(size_t(r.count(1 << 24)));
            for (double& t : s.times) t = r.f64();
            return s;
        });
    lastOpen_ = path;
    lastOptions_ = options;
    return info;
}

core::SurfaceMesh ReaderProcess::readStep(size_t index, const std::string& label) {
    std::lock_guard lock(mutex_);
    return call(
        label, openBudgetS_,
        [&](wire::Writer& w) {
            w.u8(uint8_t(wire::Op::Step));
            w.u64(index);
        },
        [](wire::Reader& r) { return r.mesh(); });
}

FileInfo ReaderProcess::inspect(const std::string& path, const SourceOptions& options) {
    std::lock_guard lock(mutex_);
    return call(
        path, budgetFor(path),
        [&](wire::Writer& w) {
            w.u8(uint8_t(wire::Op::Inspect));
            w.str(path);
            wire::writeSourceOptions(w, options);
        },
        [](wire::Reader& r) { return wire::readFileInfo(r); });
}

}  // namespace flowsurf::io::detail
