// flowsurf — the wire between the library and its reader process (private to src/io):
// length-prefixed little-endian records over one AF_UNIX stream socket. A request
// (Request) carries the child's budgets, an op and its arguments; a reply is a status,
// then the payload (a SourceInfo, a surface mesh, a FileInfo) or the error's text, then
// the reader's warnings.
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
// Reply status: the error type the reader threw, rethrown as the same type.
enum class Status : uint8_t { Ok = 0, IoError = 1, FormatError = 2, ConfigError = 3, FieldError = 4, Other = 5 };

template <typename T>
concept Plain = std::is_trivially_copyable_v<T>;
// A record's object: const when written, filled when read.
template <typename T, typename Of>
concept Is = std::same_as<std::remove_const_t<T>, Of>;

// Buffered writes to a socket; flush() sends everything (no SIGPIPE: a dead peer is an
// error the reader side reports).
class Writer {
public:
    explicit Writer(int fd) : fd_(fd) {}
    // False if the peer is gone.
    bool flush();

    template <Plain T>
    void field(const T& v) { raw(&v, sizeof v); }
    void field(const std::string& s) {
        field(uint64_t(s.size()));
        raw(s.data(), s.size());
    }
    template <typename T>
    void field(const std::vector<T>& v) {
        field(uint64_t(v.size()));
        if constexpr (Plain<T>) raw(v.data(), v.size() * sizeof(T));
        else for (const T& item : v) field(item);
    }
    void field(const std::map<std::string, std::string>& m) {
        field(uint64_t(m.size()));
        for (const auto& [key, value] : m) field(key), field(value);
    }
    template <typename T, typename Each>
    void list(const std::vector<T>& v, Each each) {
        field(uint64_t(v.size()));
        for (const T& item : v) each(item);
    }

private:
    void raw(const void* data, size_t bytes);
    int fd_;
    std::vector<char> buf_;
};

// Reads from a socket until `deadline`; every read throws wire::Broken on end of stream,
// error or timeout (`timedOut` tells which), and on a count beyond any plausible size.
struct Broken {
    bool timedOut = false;
};
class Reader {
public:
    using Clock = std::chrono::steady_clock;
    explicit Reader(int fd, Clock::time_point deadline = Clock::time_point::max()) : fd_(fd), deadline_(deadline) {}

    template <typename T>
    T get() {
        T v{};
        field(v);
        return v;
    }
    template <Plain T>
    void field(T& v) { raw(&v, sizeof v); }
    void field(std::string& s) {
        s.resize(size_t(count(kMaxBytes)));
        raw(s.data(), s.size());
    }
    template <typename T>
    void field(std::vector<T>& v) {
        if constexpr (Plain<T>) {
            v.resize(size_t(count(kMaxBytes / sizeof(T))));
            raw(v.data(), v.size() * sizeof(T));
        } else {
            list(v, [&](T& item) { field(item); });
        }
    }
    void field(std::map<std::string, std::string>& m) {
        for (uint64_t i = 0, n = count(kMaxItems); i < n; ++i) {
            const auto key = get<std::string>();
            m[key] = get<std::string>();
        }
    }
    template <typename T, typename Each>
    void list(std::vector<T>& v, Each each) {
        v.resize(size_t(count(kMaxItems)));
        for (T& item : v) each(item);
    }

    static constexpr uint64_t kMaxBytes = uint64_t(1) << 34;  // far above any real mesh
    static constexpr uint64_t kMaxItems = uint64_t(1) << 20;  // arrays, parts, warnings

private:
    uint64_t count(uint64_t limit);  // a count of at most `limit`
    void raw(void* data, size_t bytes);
    int fd_;
    Clock::time_point deadline_;
};

// One request: the op and its arguments (Open and Inspect: a path and its options; Step:
// an index), and the child's budgets for it (CPU seconds, address space in MiB).
struct Request {
    Op op = Op::Quit;
    std::string path;
    SourceOptions options;
    uint64_t step = 0;
    uint64_t cpuSeconds = 0, memoryMb = 0;
};
// Open's reply: the source's format and times.
struct SourceInfo {
    std::string format;
    std::vector<double> times;
};

// Each record's layout, written once and run both ways: with a Writer on a const object,
// with a Reader on one to fill.
template <typename Io, Is<Request> R>
void record(Io& io, R& r) {
    io.field(r.cpuSeconds);
    io.field(r.memoryMb);
    io.field(r.op);
    if (r.op == Op::Open || r.op == Op::Inspect) {
        io.field(r.path);
        io.field(r.options.patches);
        io.field(r.options.foamCase);
    }
    if (r.op == Op::Step) io.field(r.step);
}

template <typename Io, Is<SourceInfo> Info>
void record(Io& io, Info& s) {
    io.field(s.format);
    io.field(s.times);
}

template <typename Io, Is<core::SurfaceMesh> Mesh>
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

template <typename Io, Is<FileInfo> Info>
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
        io.field(p.arrays);
    });
    io.field(info.times);
    io.field(info.bounds);
}

}  // namespace flowsurf::io::wire
