// Legacy layout (www.vtk.org/VTK/img/file-formats.pdf): 4 header lines, then keyword
// lines each followed by their data, ASCII tokens or big-endian binary ending in '\n'.
#include "io/legacy_check.h"

#include "core/errors.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace flowsurf::io::detail {

namespace {

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return s;
}

// Bytes per value in BINARY files; 0 for types this check does not skip.
size_t binaryWidth(const std::string& type) {
    const std::string t = upper(type);
    if (t == "UNSIGNED_CHAR" || t == "CHAR" || t == "SIGNED_CHAR") return 1;
    if (t == "SHORT" || t == "UNSIGNED_SHORT") return 2;
    if (t == "INT" || t == "UNSIGNED_INT" || t == "FLOAT" || t == "VTKIDTYPE" || t == "VTKTYPEINT32" ||
        t == "VTKTYPEUINT32")
        return 4;
    if (t == "LONG" || t == "UNSIGNED_LONG" || t == "DOUBLE" || t == "VTKTYPEINT64" || t == "VTKTYPEUINT64")
        return 8;
    return 0;
}

class Scanner {
public:
    Scanner(const std::string& path, bool binary, std::ifstream& in) : path_(path), binary_(binary), in_(in) {}

    // The next keyword line split into words (METADATA blocks skipped); empty at the end.
    std::vector<std::string> keyword() {
        std::string line;
        while (std::getline(in_, line)) {
            std::istringstream s(line);
            std::vector<std::string> words;
            for (std::string w; s >> w;) words.push_back(w);
            if (words.empty()) continue;
            if (upper(words[0]) == "METADATA") {
                while (std::getline(in_, line) && line.find_first_not_of(" \t\r") != std::string::npos) {
                }
                continue;
            }
            return words;
        }
        return {};
    }

    void skip(uint64_t count, size_t width, const std::string& section) {
        if (binary_) {
            in_.ignore(std::streamsize(count * width));
            if (uint64_t(in_.gcount()) != count * width) truncated(section);
            return;
        }
        // Every token must be a number: VTK's ASCII cell reader crashes on one that is not.
        std::string token;
        for (uint64_t i = 0; i < count; ++i) {
            if (!(in_ >> token)) truncated(section);
            char* end = nullptr;
            std::strtod(token.c_str(), &end);
            if (*end) notANumber(section, token);
        }
    }

    int64_t readInt(const std::string& section) {
        if (binary_) {
            unsigned char b[4];
            if (!in_.read(reinterpret_cast<char*>(b), 4)) truncated(section);
            return int32_t(uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | b[3]);
        }
        std::string token;
        if (!(in_ >> token)) truncated(section);
        char* end = nullptr;
        long long v = std::strtoll(token.c_str(), &end, 10);
        if (*end || end == token.c_str()) notANumber(section, token);
        return v;
    }

    [[noreturn]] void notANumber(const std::string& section, const std::string& token) const {
        std::string shown = token.substr(0, 20);
        for (auto& c : shown)
            if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
        throw FormatError(path_ + ": VTK legacy " + section + " data: '" + shown + "' is not a number");
    }

    [[noreturn]] void truncated(const std::string& section) const {
        throw FormatError(path_ + ": truncated VTK legacy file: the " + section + " data ends early");
    }

private:
    const std::string& path_;
    bool binary_;
    std::ifstream& in_;
};

uint64_t count(const std::vector<std::string>& words, size_t i, const std::string& path) {
    long long v = i < words.size() ? std::strtoll(words[i].c_str(), nullptr, 10) : -1;
    if (v < 0) throw FormatError(path + ": VTK legacy section " + words[0] + " has a bad count");
    return uint64_t(v);
}

// "count id id ..." runs: n cells in `size` integers.
void checkCellList(Scanner& scan, const std::vector<std::string>& words, const std::string& path) {
    const std::string section = upper(words[0]);
    const uint64_t cells = count(words, 1, path), size = count(words, 2, path);
    uint64_t used = 0;
    for (uint64_t c = 0; c < cells; ++c) {
        const int64_t n = used < size ? scan.readInt(section) : -1;
        if (n < 0 || used + 1 + uint64_t(n) > size)
            throw FormatError(path + ": VTK legacy " + section + " cell " + std::to_string(c) +
                              " does not fit the declared size " + std::to_string(size));
        scan.skip(uint64_t(n), 4, section);
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
    const std::string mode = upper(encoding.substr(0, encoding.find_last_not_of(" \t\r") + 1));
    if (mode != "ASCII" && mode != "BINARY")
        throw FormatError(path + ": VTK legacy line 3 must be ASCII or BINARY");
    Scanner scan(path, mode == "BINARY", in);

    for (auto words = scan.keyword(); !words.empty(); words = scan.keyword()) {
        const std::string key = upper(words[0]);
        if (key == "DATASET") {
            const std::string type = words.size() > 1 ? upper(words[1]) : "";
            if (type != "POLYDATA" && type != "UNSTRUCTURED_GRID") return;  // no explicit cells
        } else if (key == "POINTS") {
            const size_t width = words.size() > 2 ? binaryWidth(words[2]) : 0;
            if (width == 0) return;
            scan.skip(count(words, 1, path) * 3, width, "POINTS");
        } else if (key == "FIELD") {
            for (uint64_t a = 0, n = count(words, 2, path); a < n; ++a) {
                auto array = scan.keyword();
                if (array.empty()) scan.truncated("FIELD");
                if (upper(array[0]) == "NULL_ARRAY") continue;
                const size_t width = array.size() > 3 ? binaryWidth(array[3]) : 0;
                if (width == 0) return;  // strings, bits...: left to VTK
                scan.skip(count(array, 1, path) * count(array, 2, path), width, "FIELD");
            }
        } else if (key == "VERTICES" || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS" ||
                   key == "CELLS") {
            checkCellList(scan, words, path);
        } else if (key == "CELL_TYPES") {
            scan.skip(count(words, 1, path), 4, "CELL_TYPES");
        } else {
            return;  // POINT_DATA / CELL_DATA (attributes are sized arrays) or unknown
        }
    }
}

}  // namespace flowsurf::io::detail
