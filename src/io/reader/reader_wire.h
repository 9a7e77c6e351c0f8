// flowsurf — the wire between the library and its reader process (private to src/io):
// length-prefixed little-endian records over one AF_UNIX stream socket. Requests carry
// the child's budgets (CPU seconds, address space in MiB), an op and its arguments;
// replies a status (ok, or the typed error the reader threw) and the payload: the
// metadata of a source, a surface mesh (one step of it), a FileInfo.
#pragma once

#include "core/mesh.h"
#include "io/dataset_reader.h"

#include <chrono>
#include <concepts>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace flowsurf::io::wire {

enum class Op : uint8_t { Open = 1, Step = 2, Inspect = 4, Quit = 5 };
// Reply status: the error type the reader threw, rethrown as the same type. Every reply,
// ok or not, ends with the reader's warnings (a count and the texts).
enum class Status : uint8_t { Ok = 0, IoError = 1, FormatError = 2, ConfigError = 3, FieldError = 4, Other = 5 };

// Buffered writes to a socket; flush() sends everything (no SIGPIPE: a dead peer is an
// error the reader side reports). field() and list() write what record() lays out.
class Writer {
public:
    explicit Writer(int fd) : fd_(fd) {}
    void u8(uint8_t v) { raw(&v, 1); }
    void u64(uint64_t v) { raw(&v, 8); }
    void str(const std::string& s);
    void raw(const void* data, size_t bytes);
    // False if the peer is gone.
    bool flush();

    template <typename T>
        requires std::is_trivially_copyable_v<T>
    void field(const T& v) { raw(&v, sizeof v); }
    template <typename T>
        requires std::is_trivially_copyable_v<T>
    void field(const std::vector<T>& v) {
        u64(v.size());
        raw(v.data(), v.size() * sizeof(T));
    }
    void field(const std::string& s) { str(s); }
    void field(const std::map<std::string, std::string>& m);
    template <typename T, typename Each>
    void list(const std::vector<T>& v, Each each) {
        u64(v.size());
        for (const T& item : v) each(item);
    }

private:
    int fd_;
    std::vector<char> buf_;
};

// Reads from a socket until `deadline`; every read throws wire::Broken on end of stream,
// error or timeout (`timedOut()` tells which), and on a count beyond any plausible size.
struct Broken {
    bool timedOut = false;
};
class Reader {
public:
    using Clock = std::chrono::steady_clock;
    explicit Reader(int fd, Clock::time_point deadline = Clock::time_point::max()) : fd_(fd), deadline_(deadline) {}
    uint8_t u8();
    uint64_t u64();
    std::string str();
    // A count of at most `limit`.
    uint64_t count(uint64_t limit);
    void raw(void* data, size_t bytes);

    template <typename T>
        requires std::is_trivially_copyable_v<T>
    void field(T& v) { raw(&v, sizeof v); }
    template <typename T>
        requires std::is_trivially_copyable_v<T>
    void field(std::vector<T>& v) {
        v.resize(size_t(count(kMaxBytes / sizeof(T))));
        raw(v.data(), v.size() * sizeof(T));
    }
    void field(std::string& s) { s = str(); }
    void field(std::map<std::string, std::string>& m);
    template <typename T, typename Each>
    void list(std::vector<T>& v, Each each) {
        v.resize(size_t(count(1 << 20)));
        for (T& item : v) each(item);
    }

    static constexpr uint64_t kMaxBytes = uint64_t(1) << 34;  // far above any real mesh

private:
    int fd_;
    Clock::time_point deadline_;
};

// Each record's layout, written once and run both ways: with a Writer on a const object,
// with a Reader on one to fill.
template <typename Io, typename Mesh>
    requires std::same_as<std::remove_const_t<Mesh>, core::SurfaceMesh>
void record(Io& io, Mesh& m) {
    io.field(m.positions);
    io.field(m.normals);
    io.field(m.triangles);
    const auto named = [&](auto& f) {
        io.field(f.name);
        io.field(f.values);
    };
    io.list(m.fields, named);
    io.list(m.scalars, named);
    io.field(m.units);
}

template <typename Io, typename Info>
    requires std::same_as<std::remove_const_t<Info>, FileInfo>
void record(Io& io, Info& info) {
    io.field(info.path);
    io.field(info.format);
    io.field(info.points);
    io.field(info.triangles);
    io.list(info.arrays, [&](auto& a) {
        io.field(a.name);
        io.field(a.components);
        io.field(a.pointData);
        io.field(a.rangeMin);
        io.field(a.rangeMax);
        io.field(a.units);
    });
    io.list(info.parts, [&](auto& p) {
        io.field(p.name);
        io.field(p.faces);
        io.list(p.arrays, [&](auto& name) { io.field(name); });
    });
    io.field(info.times);
    io.field(info.bounds);
}

template <typename Io, typename Options>
    requires std::same_as<std::remove_const_t<Options>, SourceOptions>
void record(Io& io, Options& o) {
    io.field(o.patches);
    io.field(o.foamCase);
}

}  // namespace flowsurf::io::wire
