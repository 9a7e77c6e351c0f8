#include "io/reader/reader_wire.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace flowsurf::io::wire {

namespace {
constexpr uint64_t kMaxCount = uint64_t(1) << 34;  // far above any real mesh; guards a corrupt stream

template <typename T>
void writeVector(Writer& w, const std::vector<T>& v) {
    w.u64(v.size());
    w.raw(v.data(), v.size() * sizeof(T));
}
template <typename T>
void readVector(Reader& r, std::vector<T>& v) {
    v.resize(size_t(r.count(kMaxCount / sizeof(T))));
    r.raw(v.data(), v.size() * sizeof(T));
}
}  // namespace

void Writer::raw(const void* data, size_t bytes) {
    const char* p = static_cast<const char*>(data);
    buf_.insert(buf_.end(), p, p + bytes);
    if (buf_.size() > (size_t(1) << 20)) flush();
}

void Writer::str(const std::string& s) {
    u64(s.size());
    raw(s.data(), s.size());
}

void Writer::mesh(const core::SurfaceMesh& m) {
    writeVector(*this, m.positions);
    writeVector(*this, m.normals);
    writeVector(*this, m.triangles);
    u64(m.fields.size());
    for (const auto& f : m.fields) {
        str(f.name);
        writeVector(*this, f.values);
    }
    u64(m.scalars.size());
    for (const auto& f : m.scalars) {
        str(f.name);
        writeVector(*this, f.values);
    }
    u64(m.units.size());
    for (const auto& [name, units] : m.units) {
        str(name);
        str(units);
    }
}

bool Writer::flush() {
    size_t done = 0;
    bool ok = true;
    while (done < buf_.size()) {
        ssize_t n = ::send(fd_, buf_.data() + done, buf_.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = false;
            break;
        }
        done += size_t(n);
    }
    buf_.clear();
    return ok;
}

void Reader::raw(void* data, size_t bytes) {
    char* p = static_cast<char*>(data);
    while (bytes > 0) {
        if (deadline_ != Clock::time_point::max()) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count();
            if (left <= 0) throw Broken{true};
            pollfd pfd{fd_, POLLIN, 0};
            int rc = ::poll(&pfd, 1, int(std::min<long long>(left, 1 << 30)));
            if (rc < 0 && errno == EINTR) continue;
            if (rc == 0) throw Broken{true};
            if (rc < 0) throw Broken{};
        }
        ssize_t n = ::recv(fd_, p, bytes, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Broken{};
        p += n;
        bytes -= size_t(n);
    }
}

uint8_t Reader::u8() {
    uint8_t v;
    raw(&v, 1);
    return v;
}
uint64_t Reader::u64() {
    uint64_t v;
    raw(&v, 8);
    return v;
}
double Reader::f64() {
    double v;
    raw(&v, 8);
    return v;
}
uint64_t Reader::count(uint64_t limit) {
    uint64_t n = u64();
    if (n > limit) throw Broken{};
    return n;
}
std::string Reader::str() {
    std::string s(size_t(count(kMaxCount)), '\0');
    raw(s.data(), s.size());
    return s;
}

core::SurfaceMesh Reader::mesh() {
    core::SurfaceMesh m;
    readVector(*this, m.positions);
    readVector(*this, m.normals);
    readVector(*this, m.triangles);
    m.fields.resize(size_t(count(1 << 20)));
    for (auto& f : m.fields) {
        f.name = str();
        readVector(*this, f.values);
    }
    m.scalars.resize(size_t(count(1 << 20)));
    for (auto& f : m.scalars) {
        f.name = str();
        readVector(*this, f.values);
    }
    for (uint64_t i = 0, n = count(1 << 20); i < n; ++i) {
        std::string name = str();
        m.units[name] = str();
    }
    return m;
}

void writeSourceOptions(Writer& w, const SourceOptions& o) {
    w.str(o.patches);
    w.str(o.foamCase);
}

SourceOptions readSourceOptions(Reader& r) {
    SourceOptions o;
    o.patches = r.str();
    o.foamCase = r.str();
    return o;
}

void writeFileInfo(Writer& w, const FileInfo& info) {
    w.str(info.path);
    w.str(info.format);
    w.u64(info.points);
    w.u64(info.triangles);
    w.u64(info.arrays.size());
    for (const auto& a : info.arrays) {
        w.str(a.name);
        w.u64(uint64_t(a.components));
        w.u8(a.pointData);
        w.f64(a.rangeMin);
        w.f64(a.rangeMax);
        w.str(a.units);
    }
    w.u64(info.parts.size());
    for (const auto& p : info.parts) {
        w.str(p.name);
        w.u64(p.faces);
        w.u64(p.arrays.size());
        for (const auto& a : p.arrays) w.str(a);
    }
    writeVector(w, info.times);
    w.raw(&info.bounds, sizeof(info.bounds));
}

FileInfo readFileInfo(Reader& r) {
    FileInfo info;
    info.path = r.str();
    info.format = r.str();
    info.points = size_t(r.u64());
    info.triangles = size_t(r.u64());
    info.arrays.resize(size_t(r.count(1 << 20)));
    for (auto& a : info.arrays) {
        a.name = r.str();
        a.components = int(r.u64());
        a.pointData = r.u8() != 0;
        a.rangeMin = r.f64();
        a.rangeMax = r.f64();
        a.units = r.str();
    }
    info.parts.resize(size_t(r.count(1 << 20)));
    for (auto& p : info.parts) {
        p.name = r.str();
        p.faces = size_t(r.u64());
        p.arrays.resize(size_t(r.count(1 << 20)));
        for (auto& a : p.arrays) a = r.str();
    }
    readVector(r, info.times);
    r.raw(&info.bounds, sizeof(info.bounds));
    return info;
}

}  // namespace flowsurf::io::wire
