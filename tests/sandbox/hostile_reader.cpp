// A stand-in for flowsurf-reader (through FLOWSURF_READER) that starts as the real one
// does (sandbox::start: limits, Landlock, the system-call filter), reads one request and
// then misbehaves as FLOWSURF_TEST_HOSTILE says:
//   socket   opens a TCP socket          write   creates a file next to the input
//   exec     runs /bin/true              fork    starts a process
//   outside  reads /etc/hostname         spin    burns CPU until stopped
//   signal   signals its parent (signal 0: only asks whether it exists)
//   memory   allocates until refused
// What the sandbox lets through is answered as an error saying so ("... was not
// stopped"), which the tests then see instead of the sandbox's refusal.
#include "io/reader/reader_wire.h"
#include "io/reader/sandbox.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace sandbox = flowsurf::io::sandbox;
namespace wire = flowsurf::io::wire;

namespace {

// What the call did when the sandbox let it through: its result, or its errno.
std::string misbehave(const std::string& what, const std::string& input) {
    if (what == "socket") return socket(AF_INET, SOCK_STREAM, 0) >= 0 ? "socket opened" : std::strerror(errno);
    if (what == "write") {
        const std::string file = input.substr(0, input.rfind('/') + 1) + "written";
        return ::open(file.c_str(), O_WRONLY | O_CREAT, 0644) >= 0 ? "file created" : std::strerror(errno);
    }
    if (what == "exec") {
        char* argv[] = {const_cast<char*>("/bin/true"), nullptr};
        execv("/bin/true", argv);
        return std::strerror(errno);
    }
    if (what == "fork") return fork() >= 0 ? "process started" : std::strerror(errno);
    if (what == "signal") return kill(getppid(), 0) == 0 ? "parent signalled" : std::strerror(errno);
    if (what == "outside") return ::open("/etc/hostname", O_RDONLY) >= 0 ? "read outside" : std::strerror(errno);
    if (what == "spin")
        for (unsigned long i = 0;; ++i) asm volatile("" : "+r"(i));  // not optimised away
    if (what == "memory") {
        std::vector<std::vector<char>> blocks;
        for (;;) blocks.emplace_back(size_t(64) << 20, '\1');
    }
    return "unknown FLOWSURF_TEST_HOSTILE";
}

}  // namespace

int main(int argc, char** argv) {
    sandbox::start(argc, argv);
    wire::Reader in(sandbox::kSocketFd);
    wire::Request request;  // Open: a path and its options
    wire::record(in, request);
    sandbox::limitRequest(request.memoryMb, request.cpuSeconds);
    const std::string& path = request.path;
    const char* what = std::getenv("FLOWSURF_TEST_HOSTILE");
    wire::Writer out(sandbox::kSocketFd);
    std::string result;
    try {
        result = misbehave(what ? what : "", path);
    } catch (const std::bad_alloc&) {
        result = "needed more than " + std::to_string(sandbox::memoryLimitMb()) + " MiB";
    }
    out.field(wire::Status::FormatError);
    out.field(path + ": " + (what ? what : "") + " was not stopped: " + result);
    out.field(std::vector<std::string>{});  // no warnings
    out.flush();
    return 0;
}
