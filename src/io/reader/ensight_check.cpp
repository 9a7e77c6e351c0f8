// EnSight Gold layout (EnSight User Manual, "EnSight Gold Case File Format" and
// "EnSight Gold Geometry File Format"). Sections: the geometry walk · ASCII files ·
// C binary files · the case file.
//
// Geometry: 2 description lines, "node id <off|given|assign|ignore>", "element id ...",
// optional "extents", then parts: "part", its number, a description, then "coordinates"
// (nn; nn ids if given; x, y, z) or "block [options]" (i j k; coordinates), then element
// blocks "<type>" (ne; ne ids if given; connectivity). ASCII files hold one value per
// line (one element per line); C binary files hold 80-byte strings and 4-byte ints and
// floats. A single-file time series wraps each step in BEGIN/END TIME STEP.
#include "io/reader/ensight_check.h"

#include "core/errors.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

constexpr uint64_t kTooMany = UINT64_MAX;

uint64_t mul(uint64_t a, uint64_t b) {
    uint64_t r;
    return __builtin_mul_overflow(a, b, &r) ? kTooMany : r;
}
uint64_t add(uint64_t a, uint64_t b) {
    uint64_t r;
    return __builtin_add_overflow(a, b, &r) ? kTooMany : r;
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// The file read-only in memory (an empty file maps to nothing).
class Mapping {
public:
    explicit Mapping(const std::string& path) {
        const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) return;
        struct stat st {};
        if (::fstat(fd, &st) == 0 && st.st_size > 0) {
            void* p = ::mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
            if (p != MAP_FAILED) {
                data_ = static_cast<const char*>(p);
                size_ = size_t(st.st_size);
            }
        }
        ::close(fd);
    }
    ~Mapping() {
        if (data_) ::munmap(const_cast<char*>(data_), size_);
    }
    Mapping(const Mapping&) = delete;
    Mapping& operator=(const Mapping&) = delete;
    std::string_view bytes() const { return {data_, size_}; }

private:
    const char* data_ = nullptr;
    size_t size_ = 0;
};

// Nodes per element of each type ("g_" ghost types alike); 0: nsided, -1: nfaced.
int nodesPerElement(std::string_view type) {
    if (startsWith(type, "g_")) type.remove_prefix(2);
    static const std::pair<const char*, int> kTypes[] = {
        {"point", 1},     {"bar2", 2},      {"bar3", 3},     {"tria3", 3},   {"tria6", 6},
        {"quad4", 4},     {"quad8", 8},     {"tetra4", 4},   {"tetra10", 10}, {"pyramid5", 5},
        {"pyramid13", 13}, {"penta6", 6},   {"penta15", 15}, {"hexa8", 8},   {"hexa20", 20},
        {"nsided", 0},    {"nfaced", -1}};
    for (const auto& [name, nodes] : kTypes)
        if (type == name) return nodes;
    return -2;
}

// What a count is about, for messages: "part 3 'tria3' declares 1000000000 elements".
struct Section {
    int64_t part = -1;
    std::string keyword;
    std::string unit;
    uint64_t count = 0;
};

std::string describe(const std::string& path, const Section& s) {
    std::string where = path + ": EnSight ";
    if (s.part >= 0) where += "part " + std::to_string(s.part) + " ";
    return where + "'" + s.keyword + "' declares " + std::to_string(s.count) + " " + s.unit;
}

// --- the geometry walk -----------------------------------------------------------------
// `File` reads one format (AsciiFile, BinaryFile): keyword() is the next section keyword
// (lower case; empty for an ASCII data line met outside a section; nullopt at the end),
// count() the next count (nullopt: not a number, left to VTK), data(s, ascii, binary)
// skips a section's data (ASCII: lines, binary: 4-byte values) and throws if the file
// ends first; ids(s, n) skips the n ids the header lists; sum(s, n) reads n counts
// and returns their sum (nsided, nfaced). Parts the walk does not understand end it.
struct Ids {
    bool nodes = false, elements = false;
};

template <class File>
void walkGeometry(File& f) {
    Ids ids;
    if (!f.header(ids)) return;
    Section s;
    uint64_t blockNodes = 0, blockCells = 0;  // of the last structured part
    for (std::optional<std::string> kw = f.keyword(); kw; kw = f.keyword()) {
        const std::string& k = *kw;
        s.keyword = k.substr(0, k.find_first_of(" \t"));
        if (k.empty() || k == "extents") continue;  // extents: data lines (ASCII) or skipped in keyword()
        if (startsWith(k, "begin time step")) {
            if (!f.header(ids)) return;
            continue;
        }
        if (startsWith(k, "end time step")) continue;
        if (s.keyword == "part") {
            s.part = f.partNumber();
            continue;
        }
        if (s.keyword == "coordinates") {
            auto n = f.count();
            if (!n) return;
            s.unit = "nodes", s.count = *n;
            f.ids(s, ids.nodes ? *n : 0);
            f.data(s, mul(3, *n), mul(3, *n));
        } else if (s.keyword == "block") {
            auto dims = f.dims(k.find("range") != std::string::npos);
            if (!dims) return;
            const auto [i, j, k3] = *dims;
            blockNodes = mul(mul(i, j), k3);
            blockCells = mul(mul(std::max<uint64_t>(i, 2) - 1, std::max<uint64_t>(j, 2) - 1),
                             std::max<uint64_t>(k3, 2) - 1);
            s.unit = "nodes (" + std::to_string(i) + " x " + std::to_string(j) + " x " + std::to_string(k3) + ")";
            s.count = blockNodes;
            uint64_t values = mul(3, blockNodes);  // curvilinear, the default
            if (k.find("rectilinear") != std::string::npos) values = add(add(i, j), k3);
            if (k.find("uniform") != std::string::npos) values = 6;
            f.data(s, values, values);
            if (k.find("iblanked") != std::string::npos) f.data(s, blockNodes, blockNodes);
        } else if (s.keyword == "ghost_flags" || s.keyword == "element_ids" || s.keyword == "node_ids") {
            const uint64_t n = s.keyword == "node_ids" ? blockNodes : blockCells;
            s.unit = s.keyword == "node_ids" ? "nodes" : "cells", s.count = n;
            f.data(s, n, n);
        } else if (const int nodes = nodesPerElement(s.keyword); nodes > -2) {
            auto n = f.count();
            if (!n) return;
            s.unit = "elements", s.count = *n;
            f.ids(s, ids.elements ? *n : 0);
            if (nodes > 0) {
                f.data(s, *n, mul(*n, uint64_t(nodes)));
            } else if (nodes == 0) {  // nsided: nodes per element, then the nodes
                auto total = f.sum(s, *n);
                if (!total) return;
                f.data(s, *n, *total);
            } else {  // nfaced: faces per element, nodes per face, then the nodes
                auto faces = f.sum(s, *n);
                if (!faces) return;
                s.unit = "faces", s.count = *faces;
                auto total = f.sum(s, *faces);
                if (!total) return;
                f.data(s, *faces, *total);
            }
        } else {
            return;  // not a section this walk knows: VTK reports it
        }
    }
}

// --- ASCII files -----------------------------------------------------------------------
// Counted as VTK's reader counts: a data line has a character other than white space and
// does not start with '#'; blank and comment lines are skipped wherever it reads data.
class AsciiFile {
public:
    AsciiFile(std::string_view bytes, const std::string& path) : rest_(bytes), path_(path) {}

    bool header(Ids& ids) {
        auto first = line();
        if (first && startsWith(lower(*first), "begin time step")) first = line();
        if (!first || !line()) return false;  // the two description lines
        auto node = dataLine(), element = dataLine();
        if (!node || !element) return false;
        const std::string n = lower(*node), e = lower(*element);
        if (!startsWith(n, "node id") || !startsWith(e, "element id")) return false;
        ids.nodes = listsIds(n);
        ids.elements = listsIds(e);
        return true;
    }

    std::optional<std::string> keyword() {
        auto l = dataLine();
        if (!l) return std::nullopt;
        std::string k = lower(trim(*l));
        if (k.empty() || !std::isalpha(static_cast<unsigned char>(k[0]))) return std::string();
        return k;
    }

    int64_t partNumber() {
        auto number = dataLine();
        line();  // the description, any text
        if (!number) return -1;
        return std::strtoll(std::string(*number).c_str(), nullptr, 10);
    }

    std::optional<uint64_t> count() {
        auto l = dataLine();
        if (!l) return std::nullopt;
        return leadingInteger(*l);
    }

    std::optional<std::array<uint64_t, 3>> dims(bool range) {
        auto l = dataLine();
        if (!l) return std::nullopt;
        std::istringstream in{std::string(*l)};
        long long i = -1, j = -1, k = -1;
        if (!(in >> i >> j >> k) || i < 0 || j < 0 || k < 0) return std::nullopt;
        if (range) dataLine();  // imin imax jmin jmax kmin kmax
        return std::array<uint64_t, 3>{uint64_t(i), uint64_t(j), uint64_t(k)};
    }

    // Ids precede the data; VTK tells them apart by what the lines hold, so they are
    // skipped as far as they go and only the data lines are required.
    void ids(const Section& /*s*/, uint64_t n) {
        for (uint64_t i = 0; i < n && dataLine(); ++i) {
        }
    }

    void data(const Section& s, uint64_t lines, uint64_t /*binaryValues*/) {
        if (lines > rest_.size())
            throw FormatError(describe(path_, s) + ", more than the file holds (" + std::to_string(lines) +
                              " lines of data needed, " + std::to_string(rest_.size()) + " bytes left)");
        for (uint64_t i = 0; i < lines; ++i)
            if (!dataLine())
                throw FormatError(describe(path_, s) + ", more than the file holds (" + std::to_string(lines) +
                                  " lines of data needed, the file ends after " + std::to_string(i) + ")");
    }

    std::optional<uint64_t> sum(const Section& s, uint64_t n) {
        const std::string_view counts = rest_;
        data(s, n, n);  // the counts themselves must be there
        rest_ = counts;
        uint64_t total = 0;
        for (uint64_t i = 0; i < n; ++i) {
            auto v = leadingInteger(*dataLine());
            if (!v) return std::nullopt;
            total = add(total, *v);
        }
        return total;
    }

private:
    static bool listsIds(const std::string& line) {
        return line.find("given") != std::string::npos || line.find("ignore") != std::string::npos;
    }
    static std::string_view trim(std::string_view s) {
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
        return s;
    }
    // The count at the start of a line; a negative one is refused (no count is), text
    // is left to VTK.
    std::optional<uint64_t> leadingInteger(std::string_view l) const {
        l = trim(l);
        size_t digits = (!l.empty() && (l[0] == '-' || l[0] == '+')) ? 1 : 0;
        const size_t start = digits;
        while (digits < l.size() && std::isdigit(static_cast<unsigned char>(l[digits]))) ++digits;
        if (digits == start) return std::nullopt;
        if (l[0] == '-')
            throw FormatError(path_ + ": EnSight count '" + std::string(l.substr(0, digits)) + "' is negative");
        if (digits - start > 19) return kTooMany;
        return std::strtoull(std::string(l.substr(start, digits - start)).c_str(), nullptr, 10);
    }
    std::optional<std::string_view> line() {
        if (rest_.empty()) return std::nullopt;
        const size_t end = rest_.find('\n');
        std::string_view l = rest_.substr(0, end);
        rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        return l;
    }
    std::optional<std::string_view> dataLine() {
        for (auto l = line(); l; l = line()) {
            if (l->empty() || (*l)[0] == '#') continue;
            if (!std::isspace(static_cast<unsigned char>((*l)[0])) || !trim(*l).empty()) return l;
        }
        return std::nullopt;
    }

    std::string_view rest_;
    const std::string& path_;
};

// --- C binary files --------------------------------------------------------------------
// The byte order is the one that makes the first part number sensible (0 .. 65535), as
// VTK's reader decides it; little-endian until then.
class BinaryFile {
public:
    BinaryFile(std::string_view bytes, const std::string& path)
        : bytes_(bytes), path_(path), pos_(std::min<size_t>(80, bytes.size())) {}  // after "C Binary"

    bool header(Ids& ids) {
        auto first = string();
        if (first && startsWith(*first, "begin time step")) first = string();
        if (!first || !string()) return false;  // the two description lines
        auto node = string(), element = string();
        if (!node || !element || !startsWith(*node, "node id") || !startsWith(*element, "element id")) return false;
        ids.nodes = node->find("given") != std::string::npos || node->find("ignore") != std::string::npos;
        ids.elements = element->find("given") != std::string::npos || element->find("ignore") != std::string::npos;
        return true;
    }

    std::optional<std::string> keyword() {
        auto k = string();
        if (k && *k == "extents") {
            if (left() < 24) return std::nullopt;
            pos_ += 24;  // xmin xmax ymin ymax zmin zmax
        }
        return k;
    }

    int64_t partNumber() {
        if (left() < 4) return -1;
        if (!orderKnown_) {
            const uint32_t le = word(false), be = word(true);
            bigEndian_ = le >= 65536 && be < 65536;
            orderKnown_ = true;
        }
        const int64_t part = int32_t(word(bigEndian_));
        pos_ += 4;
        string();  // the description
        return part;
    }

    std::optional<uint64_t> count() {
        if (left() < 4) return std::nullopt;
        const int32_t n = int32_t(word(bigEndian_));
        pos_ += 4;
        if (n < 0) throw FormatError(path_ + ": EnSight count " + std::to_string(n) + " is negative");
        return uint64_t(n);
    }

    std::optional<std::array<uint64_t, 3>> dims(bool range) {
        std::array<uint64_t, 3> d{};
        for (auto& v : d) {
            auto n = count();
            if (!n) return std::nullopt;
            v = *n;
        }
        if (range) {
            if (left() < 24) return std::nullopt;
            pos_ += 24;
        }
        return d;
    }

    void ids(const Section& s, uint64_t n) { data(s, 0, n); }

    void data(const Section& s, uint64_t /*asciiLines*/, uint64_t values) {
        const uint64_t bytes = mul(values, 4);
        if (bytes > left())
            throw FormatError(describe(path_, s) + ", more than the file holds (" +
                              (bytes == kTooMany ? std::string("too many") : std::to_string(bytes)) +
                              " bytes of data needed, " + std::to_string(left()) + " left)");
        pos_ += bytes;
    }

    std::optional<uint64_t> sum(const Section& s, uint64_t n) {
        const size_t start = pos_;
        data(s, n, n);
        uint64_t total = 0;
        for (size_t p = start; p < pos_; p += 4) {
            const int32_t v = int32_t(wordAt(p, bigEndian_));
            if (v < 0) throw FormatError(describe(path_, s) + ", one with a negative count " + std::to_string(v));
            total = add(total, uint64_t(v));
        }
        return total;
    }

private:
    size_t left() const { return bytes_.size() - pos_; }
    uint32_t wordAt(size_t p, bool big) const {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) {
            const uint32_t b = static_cast<unsigned char>(bytes_[p + size_t(i)]);
            v |= big ? b << (8 * (3 - i)) : b << (8 * i);
        }
        return v;
    }
    uint32_t word(bool big) const { return wordAt(pos_, big); }
    // An 80-byte string, lower case, up to its first NUL, trimmed.
    std::optional<std::string> string() {
        if (left() < 80) return std::nullopt;
        std::string_view s = bytes_.substr(pos_, 80);
        pos_ += 80;
        s = s.substr(0, s.find('\0'));
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
        return lower(s);
    }

    std::string_view bytes_;
    const std::string& path_;
    size_t pos_ = 0;
    bool orderKnown_ = false, bigEndian_ = false;
};

void checkGeometryFile(const std::string& path) {
    Mapping m(path);
    const std::string_view bytes = m.bytes();
    const std::string start = lower(bytes.substr(0, std::min<size_t>(80, bytes.size())));
    if (start.find("fortran binary") != std::string::npos) return;  // record markers: left to VTK
    if (start.find("c binary") != std::string::npos) {
        BinaryFile f(bytes, path);
        walkGeometry(f);
    } else {
        AsciiFile f(bytes, path);
        walkGeometry(f);
    }
}

// --- the case file ---------------------------------------------------------------------
struct TimeSet {
    uint64_t steps = 0;
    long long start = 0, increment = 1;
    std::vector<long long> numbers;  // "filename numbers:", when listed
};

struct CaseFile {
    bool gold = false;
    std::string model;
    int modelTimeSet = -1;
    std::map<long long, TimeSet> timeSets;
};

// "model: [ts] [fs] name [change_coords_only [cstep]]"
void parseModel(const std::string& value, CaseFile& c) {
    std::istringstream in(value);
    std::vector<std::string> tokens;
    for (std::string t; in >> t;) tokens.push_back(t);
    auto isNumber = [](const std::string& t) {
        return !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
    };
    size_t i = 0;
    if (i + 1 < tokens.size() && isNumber(tokens[i])) c.modelTimeSet = std::atoi(tokens[i++].c_str());
    if (i + 1 < tokens.size() && isNumber(tokens[i])) ++i;  // a file set: one file, all steps
    if (i < tokens.size()) c.model = tokens[i];
}

CaseFile parseCase(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::string> lines;
    uint64_t tokens = 0;
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        std::istringstream words(l);
        for (std::string w; words >> w;) ++tokens;
        lines.push_back(l);
    }
    CaseFile c;
    std::string section;
    TimeSet* set = nullptr;
    std::vector<long long>* list = nullptr;  // a list that may go on over the next lines
    for (const std::string& raw : lines) {
        const std::string l = lower(raw);
        if (l.empty() || l[0] == '#') continue;
        const size_t colon = l.find(':');
        if (colon == std::string::npos) {
            if (list) {
                std::istringstream more(l);
                for (long long v; more >> v;) list->push_back(v);
            } else if (std::isalpha(static_cast<unsigned char>(l[0]))) {
                section = l.substr(0, l.find_first_of(" \t"));
            }
            continue;
        }
        list = nullptr;
        const std::string key = l.substr(0, colon), value = raw.substr(colon + 1);
        if (section == "format" && key == "type") {
            c.gold = l.find("gold", colon) != std::string::npos;
        } else if (section == "geometry" && key == "model") {
            parseModel(value, c);
        } else if (section == "time" && key == "time set") {
            set = &c.timeSets[std::atoll(value.c_str())];
        } else if ((section == "time" || section == "file") && key == "number of steps") {
            const long long n = std::atoll(value.c_str());
            // Each step has its time value listed in this file: no more steps than words.
            if (n < 0 || uint64_t(n) > tokens)
                throw FormatError(path + ": EnSight 'number of steps' declares " + std::to_string(n) +
                                  " steps, more than the case file lists (" + std::to_string(tokens) + " words)");
            if (set && section == "time") set->steps = uint64_t(n);
        } else if (set && section == "time" && key == "filename start number") {
            set->start = std::atoll(value.c_str());
        } else if (set && section == "time" && key == "filename increment") {
            set->increment = std::atoll(value.c_str());
        } else if (set && section == "time" && key == "filename numbers") {
            list = &set->numbers;
            std::istringstream values(value);
            for (long long v; values >> v;) list->push_back(v);
        }
    }
    return c;
}

// The geometry file of each step: a run of '*' is the step's file number, zero-padded.
std::vector<std::string> geometryFiles(const CaseFile& c, const fs::path& folder) {
    const std::string name = (folder / c.model).string();
    const size_t star = name.find('*');
    if (star == std::string::npos) return {name};
    const size_t width = name.find_first_not_of('*', star) == std::string::npos
                             ? name.size() - star
                             : name.find_first_not_of('*', star) - star;
    auto set = c.timeSets.find(c.modelTimeSet);
    if (set == c.timeSets.end()) return {};
    std::vector<std::string> files;
    const TimeSet& t = set->second;
    for (uint64_t i = 0; i < t.steps; ++i) {
        const long long number = i < t.numbers.size() ? t.numbers[i] : t.start + (long long)i * t.increment;
        std::string digits = std::to_string(number);
        if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
        files.push_back(name.substr(0, star) + digits + name.substr(star + width));
    }
    return files;
}

}  // namespace

void checkEnSightCase(const std::string& casePath) {
    const CaseFile c = parseCase(casePath);
    if (!c.gold || c.model.empty()) return;  // EnSight 6, or no geometry: VTK reports it
    for (const std::string& geometry : geometryFiles(c, fs::path(casePath).parent_path())) {
        std::error_code ec;
        if (fs::is_regular_file(geometry, ec)) checkGeometryFile(geometry);
    }
}

}  // namespace flowsurf::io::detail
