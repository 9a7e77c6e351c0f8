// The NetCDF classic layout (CDF1/2/5), big-endian throughout:
//   magic numrecs dim_list gatt_list var_list, var := name dimids vatts type vsize begin
// (https://docs.unidata.ucar.edu/netcdf-c/current/file_format_specifications.html).
#include "io/reader/checks.h"

#include "core/errors.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

namespace flowsurf::io::detail {

namespace {

// Reads the header from the file (a truncated one ends early); `size` is the file's.
class Cursor {
public:
    Cursor(std::ifstream& in, uint64_t size, const std::string& path, int version)
        : in_(in), size_(size), path_(path), version_(version) {}

    uint64_t be(size_t bytes) {
        unsigned char b[8];
        need(bytes);
        in_.read(reinterpret_cast<char*>(b), std::streamsize(bytes));
        uint64_t v = 0;
        for (size_t i = 0; i < bytes; ++i) v = (v << 8) | b[i];
        return v;
    }
    uint64_t u32() { return be(4); }
    uint64_t count() { return be(version_ == 5 ? 8 : 4); }  // NON_NEG
    uint64_t offset() { return be(version_ == 1 ? 4 : 8); }  // OFFSET
    void skip(uint64_t bytes) {
        need(bytes);
        in_.seekg(std::streamoff(bytes), std::ios::cur);
    }
    std::string name() {
        const uint64_t n = count();
        need(n);
        std::string s(size_t(n), '\0');
        in_.read(s.data(), std::streamsize(n));
        skip((n + 3) / 4 * 4 - n);
        return s;
    }
    // A list's length: 0 when ABSENT (two zero words); otherwise its tag must be `tag`.
    uint64_t list(uint64_t tag, const char* what) {
        const uint64_t t = u32(), n = count();
        if (t != tag && (t != 0 || n != 0))
            throw FormatError(path_ + ": malformed Exodus II (NetCDF) " + what + " list");
        return t == tag ? n : 0;
    }

private:
    void need(uint64_t bytes) const {
        if (!in_ || bytes > size_ - uint64_t(in_.tellg()))
            throw FormatError(path_ + ": truncated Exodus II (NetCDF) header");
    }
    std::ifstream& in_;
    uint64_t size_;
    const std::string& path_;
    int version_;
};

uint64_t typeSize(uint64_t type) {
    static const uint64_t kSizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};  // NC_BYTE .. NC_UINT64
    return type < 12 ? kSizes[type] : 0;
}

uint64_t mul(uint64_t a, uint64_t b, const std::string& path) {
    uint64_t r;
    if (__builtin_mul_overflow(a, b, &r)) throw FormatError(path + ": impossible variable sizes in the Exodus II header");
    return r;
}

struct Variable {
    std::string name;
    std::vector<uint64_t> dims;
    uint64_t type = 0, begin = 0;
};

void skipAttributes(Cursor& c, const std::string& path) {
    for (uint64_t i = 0, n = c.list(0x0C, "attribute"); i < n; ++i) {
        c.name();
        uint64_t size = typeSize(c.u32());
        if (size == 0) throw FormatError(path + ": unknown NetCDF attribute type");
        c.skip((mul(c.count(), size, path) + 3) / 4 * 4);
    }
}

struct Header {
    uint64_t numRecs = 0;
    std::vector<uint64_t> dims;  // lengths
    std::vector<Variable> vars;

    bool isRecord(const Variable& v) const { return !v.dims.empty() && dims[v.dims[0]] == 0; }
};

Header parseHeader(Cursor& c, const std::string& path, int version) {
    Header h;
    h.numRecs = c.count();
    if (h.numRecs == (version == 5 ? ~uint64_t(0) : 0xFFFFFFFFu)) h.numRecs = 0;  // streaming
    for (uint64_t i = 0, n = c.list(0x0A, "dimension"); i < n; ++i) {
        c.name();
        h.dims.push_back(c.count());
    }
    skipAttributes(c, path);
    for (uint64_t i = 0, n = c.list(0x0B, "variable"); i < n; ++i) {
        Variable v;
        v.name = c.name();
        for (uint64_t k = 0, nd = c.count(); k < nd; ++k) {
            uint64_t id = c.count();
            if (id >= h.dims.size()) throw FormatError(path + ": variable '" + v.name + "' has a bad dimension");
            v.dims.push_back(id);
        }
        skipAttributes(c, path);
        v.type = c.u32();
        if (typeSize(v.type) == 0) throw FormatError(path + ": variable '" + v.name + "' has an unknown type");
        c.count();  // vsize: recomputed from the dimensions below
        v.begin = c.offset();
        h.vars.push_back(std::move(v));
    }
    return h;
}

// Every variable's data inside the file (the netCDF library checks the header, not the
// file's length). A record variable's first dimension is the unlimited one (length 0);
// its numRecs records interleave with the other record variables'.
void checkExtents(const Header& h, uint64_t fileSize, const std::string& path) {
    auto bytesPerRecord = [&](const Variable& v) {
        uint64_t b = typeSize(v.type);
        for (size_t k = h.isRecord(v) ? 1 : 0; k < v.dims.size(); ++k) b = mul(b, h.dims[v.dims[k]], path);
        return b;
    };
    uint64_t recordSize = 0, recordVars = 0;
    for (const auto& v : h.vars)
        if (h.isRecord(v)) {
            recordSize += (bytesPerRecord(v) + 3) / 4 * 4;
            ++recordVars;
        }
    for (const auto& v : h.vars) {
        const uint64_t size = bytesPerRecord(v);
        uint64_t end = v.begin + size;
        if (h.isRecord(v))
            end = h.numRecs == 0 ? v.begin
                                 : v.begin + mul(h.numRecs - 1, recordVars == 1 ? size : recordSize, path) + size;
        if (end > fileSize || end < v.begin)
            throw FormatError(path + ": truncated Exodus II file: variable '" + v.name + "' needs " +
                              std::to_string(end) + " bytes, the file has " + std::to_string(fileSize));
    }
}

}  // namespace

void checkExodusFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);
    char magic[8] = {};
    if (ec || size < 8 || !in.read(magic, 8))
        throw FormatError(path + ": not an Exodus II file (too short or unreadable)");
    if (std::memcmp(magic, "\x89HDF\r\n\x1a\n", 8) == 0) return;  // netCDF-4: left to VTK
    const int version = magic[3];
    if (std::memcmp(magic, "CDF", 3) != 0 || (version != 1 && version != 2 && version != 5))
        throw FormatError(path + ": not an Exodus II file (neither NetCDF nor HDF5)");
    in.seekg(4);
    Cursor cursor(in, size, path, version);
    checkExtents(parseHeader(cursor, path, version), size, path);
}

}  // namespace flowsurf::io::detail
