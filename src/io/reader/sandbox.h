// flowsurf — what contains flowsurf-reader beyond its own process (private to src/io):
// resource limits, a Landlock rule set (read-only below the input's folder, where the
// kernel has Landlock) and a seccomp allow-list (libseccomp). A system call outside the
// list stops the process with SIGSYS after writing what it tried ("tried to open a
// network socket (socket)") to the reasons pipe, which the library reads when it reaps
// the child. User-facing description: doc/reader_sandbox.md.
#pragma once

#include <string>

namespace flowsurf::io::sandbox {

// The child's inherited descriptors: the request socket and the reasons pipe (write end).
constexpr int kSocketFd = 3;
constexpr int kReasonFd = 4;

// An AddressSanitizer build: no address-space limit (its shadow memory needs the room),
// and the filter answers what its error reports do (a symbolizer) with EPERM.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
constexpr bool kSanitized = __has_feature(address_sanitizer);
#else
constexpr bool kSanitized = false;
#endif

// The whole setup, from the command line the library starts the child with (--memory-mb
// N: the address space's hard limit, 0 for none; --root DIR: the folder the child may read
// below), in order: no core dumps, no file written (RLIMIT_FSIZE 0), few descriptors and
// the hard limit; then (unless FLOWSURF_READER_SANDBOX=off) Landlock below the root (where
// the kernel has it) and the system-call filter. Call once the readers' libraries are
// loaded and initialised. Throws std::runtime_error if the filter cannot be installed.
void start(int argc, char** argv);

// Per request: the soft address-space limit (clamped to the hard one; 0 leaves it) and
// `cpuSeconds` more CPU time than used so far (RLIMIT_CPU counts the process's life).
void limitRequest(unsigned long long memoryMb, unsigned long long cpuSeconds);
// The soft address-space limit in MiB, for messages (0: none).
unsigned long long memoryLimitMb();

// The folder Landlock confines reading to when `path` lies outside it; else empty.
std::string rootExcluding(const std::string& path);

}  // namespace flowsurf::io::sandbox
