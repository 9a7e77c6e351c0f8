// flowsurf — the wire between the library and its reader process (private to src/io):
// length-prefixed little-endian records over one AF_UNIX stream socket. Requests carry
// the child's budgets (CPU seconds, address space in MiB), an op and its arguments;
// replies a status (ok, or the typed error the reader threw) and the payload: the
// metadata of a source, a surface mesh (one step of it), a FileInfo.
#pragma once

#include "core/mesh.h"
#include "io/dataset_reader.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::io::wire {

enum class Op : uint8_t { Open = 1, Step = 2, Inspect = 4, Quit = 5 };
// Reply status: the error type the reader threw, rethrown as the same type. Every reply,
// ok or not, ends with the reader's warnings (a count and the texts).
enum class Status : uint8_t { Ok = 0, IoError = 1, FormatError = 2, ConfigError = 3, FieldError = 4, Other = 5 };

// Buffered writes to a socket; flush() sends everything (no SIGPIPE: a dead peer is an
// error the reader side reports).
class Writer {
public:
    explicit Writer(int fd) : fd_(fd) {}
    void u8(uint8_t v) { raw(&v, 1); }
    void u64(uint64_t v) { raw(&v, 8); }
    void f64(double v) { raw(&v, 8); }
    void str(const std::string& s);
    void mesh(const core::SurfaceMesh& m);
    void raw(const void* data, size_t bytes);
    // False if the peer is gone.
    bool flush();

private:
    int fd_;
    std::vector<char> buf_;
};

// Reads from a socket until `deadline`; every read throws wire::Broken on end of stream,
// error or timeout (`timedOut()` tells which).
struct Broken {
    bool timedOut = false;
};
class Reader {
public:
    using Clock = std::chrono::steady_clock;
    explicit Reader(int fd, Clock::time_point deadline = Clock::time_point::max()) : fd_(fd), deadline_(deadline) {}
    uint8_t u8();
    uint64_t u64();
    double f64();
    std::string str();
    core::SurfaceMesh mesh();
    // A count that must fit in what is left of the stream's plausible size.
    uint64_t count(uint64_t limit);
    void raw(void* data, size_t bytes);

private:
    int fd_;
    Clock::time_point deadline_;
};

void writeSourceOptions(Writer& w, const SourceOptions& o);
SourceOptions readSourceOptions(Reader& r);
void writeFileInfo(Writer& w, const FileInfo& info);
FileInfo readFileInfo(Reader& r);

}  // namespace flowsurf::io::wire
