// Legacy layout (www.vtk.org/VTK/img/file-formats.pdf): 4 header lines, then keywords
// with their counts, each followed by data: ASCII tokens, or big-endian binary that
// starts on the next line.
#include "io/reader/checks.h"

#include "core/errors.h"
#include "io/reader/parsers.h"  // shown

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace flowsurf::io::detail {

namespace {

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return s;
}

// VTK compares only a keyword's length ("CELLS\x1c30" is CELLS to it), so do we.
bool is(const std::string& token, const char* keyword) { return token.rfind(keyword, 0) == 0; }

// What `istream >> int` / `>> float` accept in full; VTK's reader loses its place (and
// later crashes) on anything else, "nan" and ".9" as an index included.
bool isInteger(const std::string& t) {
    size_t i = (t[0] == '+' || t[0] == '-') ? 1 : 0;
    return i < t.size() && t.find_first_not_of("0123456789", i) == std::string::npos;
}
bool isReal(const std::string& t) {
    size_t i = (t[0] == '+' || t[0] == '-') ? 1 : 0, digits = 0;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i, ++digits;
    if (i < t.size() && t[i] == '.')
        for (++i; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]));) ++i, ++digits;
    if (digits == 0) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        if (++i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        const size_t start = i;
        while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
        if (i == start) return false;
    }
    return i == t.size();
}

// Reads like vtkDataReader: whitespace-separated tokens; binary data after the rest
// of the keyword's line.
class Scanner {
public:
    Scanner(const std::string& path, bool binary, std::ifstream& in) : path_(path), binary_(binary), in_(in) {}

    // The next keyword, upper-cased; METADATA blocks (lines up to a blank one) skipped.
    std::string keyword() {
        std::string token;
        while (in_ >> token) {
            token = upper(token);
            if (!is(token, "METADATA")) return token;
            std::string line;
            std::getline(in_, line);
            while (std::getline(in_, line) && line.find_first_not_of(" \t\r") != std::string::npos) {
            }
        }
        return {};
    }

    std::string word(const std::string& section) {
        std::string token;
        if (!(in_ >> token)) truncated(section);
        return token;
    }

    uint64_t count(const std::string& section) {
        const std::string token = word(section);
        char* end = nullptr;
        const long long v = std::strtoll(token.c_str(), &end, 10);
        if (*end || end == token.c_str() || v < 0)
            throw FormatError(path_ + ": VTK legacy " + section + " has a bad count '" + shown(token) + "'");
        return uint64_t(v);
    }

    // Bytes per value of the next token's data type; 0 for strings and bits (not
    // skipped here). Anything else is refused: VTK matches type names by prefix, so a
    // garbled "float\xdd0" would shift every later count.
    size_t dataType(const std::string& section) {
        static const std::pair<const char*, size_t> kTypes[] = {
            {"UNSIGNED_CHAR", 1}, {"CHAR", 1}, {"SIGNED_CHAR", 1}, {"SHORT", 2}, {"UNSIGNED_SHORT", 2},
            {"INT", 4}, {"UNSIGNED_INT", 4}, {"FLOAT", 4}, {"VTKIDTYPE", 4}, {"VTKTYPEINT32", 4},
            {"VTKTYPEUINT32", 4}, {"LONG", 8}, {"UNSIGNED_LONG", 8}, {"DOUBLE", 8}, {"VTKTYPEINT64", 8},
            {"VTKTYPEUINT64", 8}, {"STRING", 0}, {"UTF8_STRING", 0}, {"BIT", 0}, {"VARIANT", 0}};
        const std::string type = word(section), upperType = upper(type);
        for (const auto& [name, width] : kTypes)
            if (upperType == name) return width;
        throw FormatError(path_ + ": VTK legacy " + section + " has an unknown data type '" + shown(type) + "'");
    }

    void startData() {
        std::string rest;
        if (binary_) std::getline(in_, rest);
    }

    // Skips `count` values; ASCII tokens must be numbers (integers if `integers`).
    void skip(uint64_t count, size_t width, const std::string& section, bool integers = false) {
        if (binary_) {
            in_.ignore(std::streamsize(count * width));
            if (uint64_t(in_.gcount()) != count * width) truncated(section);
            return;
        }
        for (uint64_t i = 0; i < count; ++i) {
            const std::string token = word(section);
            if (!(integers ? isInteger(token) : isReal(token))) notANumber(section, token, integers);
        }
    }

    int64_t readInt(const std::string& section) {
        if (binary_) {
            unsigned char b[4];
            if (!in_.read(reinterpret_cast<char*>(b), 4)) truncated(section);
            return int32_t(uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | b[3]);
        }
        const std::string token = word(section);
        if (!isInteger(token)) notANumber(section, token, true);
        return std::strtoll(token.c_str(), nullptr, 10);
    }

    [[noreturn]] void truncated(const std::string& section) const {
        throw FormatError(path_ + ": truncated VTK legacy file: the " + section + " data ends early");
    }
    [[noreturn]] void notANumber(const std::string& section, const std::string& token, bool integer) const {
        throw FormatError(path_ + ": VTK legacy " + section + " data: '" + shown(token) + "' is not " +
                          (integer ? "an integer" : "a number"));
    }

private:
    const std::string& path_;
    bool binary_;
    std::ifstream& in_;
};

// "count id id ..." runs: `cells` cells in `size` integers.
void checkCellList(Scanner& scan, const std::string& section, const std::string& path) {
    const uint64_t cells = scan.count(section), size = scan.count(section);
    scan.startData();
    uint64_t used = 0;
    for (uint64_t c = 0; c < cells; ++c) {
        const int64_t n = used < size ? scan.readInt(section) : -1;
        if (n < 0 || used + 1 + uint64_t(n) > size)
            throw FormatError(path + ": VTK legacy " + section + " cell " + std::to_string(c) +
                              " does not fit the declared size " + std::to_string(size));
        scan.skip(uint64_t(n), 4, section, true);
        used += 1 + uint64_t(n);
    }
    if (used != size)
        throw FormatError(path + ": VTK legacy " + section + " declares " + std::to_string(size) +
                          " integers but its " + std::to_string(cells) + " cells use " + std::to_string(used));
}

}  // namespace

void checkLegacyFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string versionLine, title, encoding;
    std::getline(in, versionLine);
    std::getline(in, title);
    std::getline(in, encoding);
    int major = 0, minor = 0;
    if (versionLine.rfind("# vtk DataFile Version ", 0) != 0 ||
        std::sscanf(versionLine.c_str() + 23, "%d.%d", &major, &minor) != 2)
        throw FormatError(path + ": not a VTK legacy file (the first line is not '# vtk DataFile Version x.y')");
    if (major >= 5) return;  // offsets + connectivity arrays: sizes are explicit, VTK reads them safely
    const std::string mode = upper(encoding);
    if (!is(mode, "ASCII") && !is(mode, "BINARY"))
        throw FormatError(path + ": VTK legacy line 3 must be ASCII or BINARY");
    Scanner scan(path, is(mode, "BINARY"), in);

    // Geometry sections in any order, up to the attribute data (sized arrays, safe).
    for (std::string key = scan.keyword(); !key.empty(); key = scan.keyword()) {
        if (is(key, "POINT_DATA") || is(key, "CELL_DATA")) {
            return;
        } else if (is(key, "DATASET")) {
            const std::string type = upper(scan.word("DATASET"));
            if (!is(type, "POLYDATA") && !is(type, "UNSTRUCTURED_GRID")) return;  // no explicit cells
        } else if (is(key, "POINTS")) {
            const uint64_t n = scan.count("POINTS");
            const size_t width = scan.dataType("POINTS");
            if (width == 0) return;
            scan.startData();
            scan.skip(n * 3, width, "POINTS");
        } else if (is(key, "FIELD")) {
            scan.word("FIELD");
            for (uint64_t a = 0, n = scan.count("FIELD"); a < n; ++a) {
                const std::string name = scan.keyword();
                if (name.empty()) scan.truncated("FIELD");
                if (is(name, "NULL_ARRAY")) continue;
                const uint64_t components = scan.count("FIELD"), tuples = scan.count("FIELD");
                const size_t width = scan.dataType("FIELD");
                if (width == 0) return;  // strings, bits: left to VTK
                scan.startData();
                scan.skip(components * tuples, width, "FIELD");
            }
        } else if (is(key, "CELL_TYPES")) {
            const uint64_t n = scan.count("CELL_TYPES");
            scan.startData();
            scan.skip(n, 4, "CELL_TYPES", true);
        } else {
            const char* list = nullptr;
            for (const char* l : {"VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS", "CELLS"})
                if (is(key, l)) list = l;
            if (!list) return;  // unknown: VTK reports it
            checkCellList(scan, list, path);
        }
    }
}

}  // namespace flowsurf::io::detail
