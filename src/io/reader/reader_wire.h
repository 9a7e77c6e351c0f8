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
#include <utility>
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

// Thrown by every read on end of stream, error or timeout (`timedOut` tells which), and
// on a count beyond any plausible size.
struct Broken {
    bool timedOut = false;
};

// One end of the socket: a Writer sends what field() is given (buffered; flush() sends it,
// false if the peer is gone; no SIGPIPE); a Reader fills it, reading until `deadline`.
// field() lays out each type the records use the same way in both directions: a plain
// value as its bytes; a string, vector or map as a count, then its items.
template <bool kWriting>
class Channel {
public:
    using Clock = std::chrono::steady_clock;
    explicit Channel(int fd, Clock::time_point deadline = Clock::time_point::max()) : fd_(fd), deadline_(deadline) {}
    bool flush();  // a Writer's

    template <typename T>
    void field(T&& v) {
        using U = std::remove_cvref_t<T>;
        if constexpr (Plain<U>) {
            raw(&v, sizeof v);
        } else if constexpr (std::same_as<U, std::map<std::string, std::string>>) {
            const uint64_t n = count(v.size(), kMaxItems);
            if constexpr (kWriting)
                for (const auto& [key, value] : v) field(key), field(value);
            else
                for (uint64_t i = 0; i < n; ++i) field(v[get<std::string>()]);
        } else {  // a string or a vector
            using Item = typename U::value_type;
            const uint64_t n = count(v.size(), Plain<Item> ? kMaxBytes / sizeof(Item) : kMaxItems);
            if constexpr (!kWriting) v.resize(size_t(n));
            if constexpr (Plain<Item>) raw(v.data(), v.size() * sizeof(Item));
            else for (auto& item : v) field(item);
        }
    }
    // A vector whose items `each` lays out.
    template <typename V, typename Each>
    void list(V& v, Each each) {
        const uint64_t n = count(v.size(), kMaxItems);
        if constexpr (!kWriting) v.resize(size_t(n));
        for (auto& item : v) each(item);
    }
    template <typename T>
    T get() requires(!kWriting) {
        T v{};
        field(v);
        return v;
    }

    static constexpr uint64_t kMaxBytes = uint64_t(1) << 34;  // far above any real mesh
    static constexpr uint64_t kMaxItems = uint64_t(1) << 20;  // arrays, parts, warnings

private:
    // Sends `n`, or reads one of at most `limit`.
    uint64_t count(uint64_t n, uint64_t limit) {
        raw(&n, sizeof n);
        if (!kWriting && n > limit) throw Broken{};
        return n;
    }
    void raw(std::conditional_t<kWriting, const void*, void*> data, size_t bytes);

    int fd_;
    Clock::time_point deadline_;
    std::vector<char> buf_;  // what a Writer has not sent yet
};
using Writer = Channel<true>;
using Reader = Channel<false>;
template <>
bool Writer::flush();
template <>
void Writer::raw(const void* data, size_t bytes);
template <>
void Reader::raw(void* data, size_t bytes);

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

// "file.pvd (time step 3 of 20, t = 0.5)" for messages about one step of many (`times`
// empty or of one: just the path), as both sides name a step.
std::string stepLabel(const std::string& path, const std::vector<double>& times, size_t index);

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
        io.field(r.options.zeroTime);
        io.field(r.options.skinFriction);
        io.field(r.options.viscosity);
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
    io.list(info.patches, [&](auto& p) {
        io.field(p.name);
        io.field(p.type);
        io.field(p.family);
        io.field(p.faces);
        io.field(p.read);
    });
    io.field(info.skinFriction);
}

}  // namespace flowsurf::io::wire
