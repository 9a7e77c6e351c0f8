// Sections: limits · reasons (SIGSYS) · Landlock · the system-call filter · start.
#include "io/reader/sandbox.h"

#include <fcntl.h>
#include <linux/landlock.h>
#include <malloc.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>

namespace flowsurf::io::sandbox {

namespace {

constexpr rlim_t kMaxDescriptors = 64;  // the readers open a handful of files at once

void setLimit(int resource, rlim_t soft, rlim_t hard) {
    rlimit r{soft, hard};
    setrlimit(resource, &r);
}

// --- limits ----------------------------------------------------------------------------
// The address space's hard limit: 0 leaves none (AddressSanitizer's shadow memory needs it).
void limitProcess(unsigned long long memoryHardMb) {
    setLimit(RLIMIT_CORE, 0, 0);
    setLimit(RLIMIT_FSIZE, 0, 0);  // a write to any regular file fails (EFBIG)
    signal(SIGXFSZ, SIG_IGN);      // ... instead of ending the process
    setLimit(RLIMIT_NOFILE, kMaxDescriptors, kMaxDescriptors);
    // Each thread's malloc arena reserves 64 MiB of address space: a few arenas keep the
    // address space near what is used, whatever the number of cores VTK's threads follow.
    mallopt(M_ARENA_MAX, 4);
    if (memoryHardMb > 0) setLimit(RLIMIT_AS, rlim_t(memoryHardMb) << 20, rlim_t(memoryHardMb) << 20);
}

}  // namespace

void limitRequest(unsigned long long memoryMb, unsigned long long cpuSeconds) {
    // Soft limits, at most the hard ones.
    const auto setSoft = [](int resource, rlim_t value) {
        rlimit r{};
        if (getrlimit(resource, &r) != 0) return;
        r.rlim_cur = r.rlim_max != RLIM_INFINITY && value > r.rlim_max ? r.rlim_max : value;
        setrlimit(resource, &r);
    };
    if (memoryMb > 0) setSoft(RLIMIT_AS, rlim_t(memoryMb) << 20);
    if (cpuSeconds > 0) {
        rusage u{};
        getrusage(RUSAGE_SELF, &u);
        const long usedUs =
            (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1000000L + u.ru_utime.tv_usec + u.ru_stime.tv_usec;
        setSoft(RLIMIT_CPU, rlim_t((usedUs + 999999) / 1000000) + rlim_t(cpuSeconds));  // used, rounded up, + budget
    }
}

unsigned long long memoryLimitMb() {
    rlimit r{};
    if (getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return 0;
    return r.rlim_cur >> 20;
}

// --- reasons (SIGSYS) --------------------------------------------------------------------
// What a refused call means to a user, and its name: both looked up by number in the
// signal handler, so both are filled in before the filter is installed.
namespace {

constexpr int kMaxSyscall = 512;
enum Kind : unsigned char { kOther, kNetwork, kProgram, kProcess, kWriteFile, kChangeFile, kTrace };
const char* const kKindText[] = {
    "made a system call its sandbox forbids", "tried to open a network socket", "tried to run a program",
    "tried to start a process",               "tried to open a file for writing", "tried to change a file",
    "tried to reach another process"};
std::array<Kind, kMaxSyscall> gKinds{};
std::array<std::array<char, 32>, kMaxSyscall> gNames{};

void classify(Kind kind, std::initializer_list<const char*> names) {
    for (const char* name : names) {
        const int nr = seccomp_syscall_resolve_name(name);
        if (nr >= 0 && nr < kMaxSyscall) gKinds[size_t(nr)] = kind;
    }
}

void fillReasons() {
    for (int nr = 0; nr < kMaxSyscall; ++nr) {
        char* name = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, nr);
        std::snprintf(gNames[size_t(nr)].data(), gNames[0].size(), "%s", name ? name : "unknown");
        std::free(name);
    }
    classify(kNetwork, {"socket", "socketpair", "connect", "bind", "listen", "accept", "accept4"});
    classify(kProgram, {"execve", "execveat"});
    classify(kProcess, {"fork", "vfork", "clone"});
    classify(kWriteFile, {"open", "openat", "creat"});
    classify(kChangeFile, {"unlink", "unlinkat", "rename", "renameat", "renameat2", "mkdir", "mkdirat", "rmdir",
                           "truncate", "ftruncate", "chmod", "fchmod", "fchmodat", "link", "linkat", "symlink",
                           "symlinkat", "mknod", "mknodat"});
    classify(kTrace, {"ptrace", "process_vm_readv", "process_vm_writev", "kcmp", "pidfd_open", "pidfd_getfd",
                      "kill", "tkill", "tgkill", "prlimit64"});
}

void append(char* buf, size_t& n, size_t cap, const char* text) {
    while (*text && n + 1 < cap) buf[n++] = *text++;
}

// "tried to open a network socket (socket)" to the reasons pipe, then the default
// action: the process ends by SIGSYS (no core: RLIMIT_CORE is 0).
void onSigsys(int, siginfo_t* info, void*) {
    char text[160];
    size_t n = 0;
    const int nr = info->si_syscall;
    const bool known = nr >= 0 && nr < kMaxSyscall;
    append(text, n, sizeof text, kKindText[known ? gKinds[size_t(nr)] : kOther]);
    append(text, n, sizeof text, " (");
    append(text, n, sizeof text, known ? gNames[size_t(nr)].data() : "unknown system call");
    append(text, n, sizeof text, ")");
    [[maybe_unused]] ssize_t w = ::write(kReasonFd, text, n);
    signal(SIGSYS, SIG_DFL);
    raise(SIGSYS);
}

// --- Landlock ----------------------------------------------------------------------------
std::string gReadableRoot;

// Read-only below `root`; every other file-system right is handled and so refused. The
// descriptors already open (libraries, the socket) are not affected.
void landlock(const std::string& root) {
#ifdef __NR_landlock_create_ruleset
    const long abi = syscall(__NR_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
    if (abi < 1) return;  // no Landlock in this kernel: the filter below still holds
    // ABI 1's rights are bits 0 (EXECUTE) to 12 (MAKE_SYM), ABI 2 adds 13 (REFER); later ones
    // (truncate, ioctl) are the system-call filter's.
    landlock_ruleset_attr attr{};
    attr.handled_access_fs = ((abi >= 2 ? LANDLOCK_ACCESS_FS_REFER : LANDLOCK_ACCESS_FS_MAKE_SYM) << 1) - 1;
    const int ruleset = int(syscall(__NR_landlock_create_ruleset, &attr, sizeof attr, 0));
    if (ruleset < 0) return;
    const int dir = ::open(root.empty() ? "/" : root.c_str(), O_PATH | O_CLOEXEC);
    if (dir >= 0) {
        landlock_path_beneath_attr beneath{};
        beneath.allowed_access = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
        beneath.parent_fd = dir;
        syscall(__NR_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &beneath, 0);
        ::close(dir);
    }
    prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
    if (syscall(__NR_landlock_restrict_self, ruleset, 0) == 0) gReadableRoot = root.empty() ? "/" : root;
    ::close(ruleset);
#else
    (void)root;
#endif
}

// --- the system-call filter --------------------------------------------------------------
// What VTK, its libraries (HDF5, NetCDF, TBB, expat, zlib), libcgns, glibc and libstdc++ use
// to read files, allocate, run threads and answer over the socket. CGNS needs nothing more:
// libcgns and VTK's copy of it open HDF5 files read-only (HDF5's file lock is flock) and
// ADF files with fopen "rb", and follow links by opening the linked file the same way. Opens are allowed read-only,
// clone for threads only; everything else stops the process (SIGSYS, onSigsys).
const char* const kAllowed[] = {
    // files already allowed to be open, and their metadata
    "read", "readv", "pread64", "preadv", "preadv2", "write", "writev", "close", "close_range", "lseek",
    "fstat", "newfstatat", "stat", "lstat", "statx", "fstatfs", "statfs", "getdents64", "getdents", "readlink",
    "readlinkat", "getcwd", "access", "faccessat", "faccessat2", "fcntl", "dup", "dup2", "dup3", "flock",
    "fadvise64",
    // memory
    "mmap", "munmap", "mremap", "mprotect", "madvise", "brk", "membarrier",
    // threads and time
    "futex", "set_robust_list", "get_robust_list", "rseq", "sched_yield", "sched_getaffinity",
    "sched_getparam", "sched_getscheduler", "getpriority", "clock_gettime", "clock_getres", "clock_nanosleep",
    "nanosleep", "gettimeofday", "time", "getpid", "gettid", "getppid", "getuid", "geteuid", "getgid",
    "getegid", "arch_prctl", "sysinfo", "uname", "getrandom",
    // limits, signals, exit (prlimit64 and tgkill: on this process only, below)
    "getrusage", "getrlimit", "setrlimit", "rt_sigaction", "rt_sigprocmask", "rt_sigreturn", "sigaltstack",
    "exit", "exit_group",
    // the request socket
    "sendto", "recvfrom", "sendmsg", "recvmsg", "poll", "ppoll"};

void addRule(scmp_filter_ctx ctx, uint32_t action, const char* name, std::initializer_list<scmp_arg_cmp> args = {}) {
    const int nr = seccomp_syscall_resolve_name(name);
    if (nr == __NR_SCMP_ERROR) return;  // not a system call on this architecture
    if (seccomp_rule_add_array(ctx, action, nr, unsigned(args.size()), args.size() ? args.begin() : nullptr) != 0)
        throw std::runtime_error(std::string("cannot add the sandbox rule for ") + name);
}

void installFilter() {
    fillReasons();
    struct sigaction sa {};
    sa.sa_sigaction = onSigsys;
    sa.sa_flags = SA_SIGINFO;
    sigaction(SIGSYS, &sa, nullptr);
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_TRAP);
    if (!ctx) throw std::runtime_error("cannot start the sandbox's system-call filter");
    struct Release {
        scmp_filter_ctx c;
        ~Release() { seccomp_release(c); }
    } release{ctx};
    seccomp_attr_set(ctx, SCMP_FLTATR_CTL_TSYNC, 1);  // threads started so far too
    for (const char* name : kAllowed) addRule(ctx, SCMP_ACT_ALLOW, name);
    const scmp_datum_t writing = O_ACCMODE | O_CREAT | O_TRUNC;
    addRule(ctx, SCMP_ACT_ALLOW, "openat", {SCMP_A2(SCMP_CMP_MASKED_EQ, writing, 0)});
    addRule(ctx, SCMP_ACT_ALLOW, "open", {SCMP_A1(SCMP_CMP_MASKED_EQ, writing, 0)});
    addRule(ctx, SCMP_ACT_ALLOW, "clone", {SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, CLONE_THREAD)});
    addRule(ctx, SCMP_ACT_ALLOW, "prlimit64", {SCMP_A0(SCMP_CMP_EQ, 0, 0)});  // glibc's own: pid 0, this process
    addRule(ctx, SCMP_ACT_ALLOW, "tgkill", {SCMP_A0(SCMP_CMP_EQ, scmp_datum_t(getpid()), 0)});  // raise(), abort()
    addRule(ctx, SCMP_ACT_ERRNO(ENOSYS), "clone3");  // flags out of reach: glibc falls back to clone
    addRule(ctx, SCMP_ACT_ERRNO(ENOSYS), "openat2");  // flags out of reach: callers fall back to openat
    addRule(ctx, SCMP_ACT_ERRNO(ENOTTY), "ioctl");    // isatty() and friends: "not a terminal"
    // Under the sanitizers: UBSan's vptr check probes memory through a pipe (allowed), and
    // an error report starts a symbolizer (answered EPERM: the report comes unsymbolized
    // instead of as a sandbox refusal). doc/reader_sandbox.md.
    if (kSanitized) {
        for (const char* name : {"pipe", "pipe2"}) addRule(ctx, SCMP_ACT_ALLOW, name);
        for (const char* name : {"fork", "vfork", "execve", "prctl", "wait4"}) addRule(ctx, SCMP_ACT_ERRNO(EPERM), name);
        addRule(ctx, SCMP_ACT_ERRNO(EPERM), "clone", {SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0)});
    }
    if (seccomp_load(ctx) != 0) throw std::runtime_error("cannot install the sandbox's system-call filter");
}

}  // namespace

std::string rootExcluding(const std::string& path) {
    if (gReadableRoot.empty()) return {};
    std::error_code ec;
    const std::filesystem::path rel = std::filesystem::weakly_canonical(path, ec).lexically_relative(gReadableRoot);
    return ec || rel.empty() || *rel.begin() == ".." ? gReadableRoot : std::string();
}

// --- start -----------------------------------------------------------------------------
void start(int argc, char** argv) {
    unsigned long long memoryHardMb = 0;
    std::string root;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--memory-mb") memoryHardMb = std::strtoull(argv[i + 1], nullptr, 10);
        else if (key == "--root") root = argv[i + 1];
    }
    limitProcess(memoryHardMb);
    const char* off = std::getenv("FLOWSURF_READER_SANDBOX");  // "off" or "0": limits only, for debugging
    if (off && (std::strcmp(off, "off") == 0 || std::strcmp(off, "0") == 0)) return;
    landlock(root);
    installFilter();
}

}  // namespace flowsurf::io::sandbox
