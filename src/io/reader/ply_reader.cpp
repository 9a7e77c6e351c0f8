// Sections: scalar types · header · body values · readPly.
#include "io/reader/parsers.h"

#include "core/errors.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <vector>

namespace flowsurf::io::detail {

namespace {

// --- scalar types ----------------------------------------------------------------------
// Each PLY scalar type by its two names, its size in bytes and its kind.
struct Scalar {
    const char* names[2];
    unsigned size;
    char kind;  // 'i' signed integer, 'u' unsigned integer, 'f' IEEE floating point
};
constexpr Scalar kScalars[] = {
    {{"char", "int8"}, 1, 'i'}, {{"uchar", "uint8"}, 1, 'u'},  {{"short", "int16"}, 2, 'i'},
    {{"ushort", "uint16"}, 2, 'u'}, {{"int", "int32"}, 4, 'i'}, {{"uint", "uint32"}, 4, 'u'},
    {{"float", "float32"}, 4, 'f'}, {{"double", "float64"}, 8, 'f'}};

const Scalar* parseScalar(const std::string& name) {
    for (const Scalar& s : kScalars)
        if (name == s.names[0] || name == s.names[1]) return &s;
    return nullptr;
}

// --- header ----------------------------------------------------------------------------
struct Property {
    std::string name;
    const Scalar* type = nullptr;
    bool isList = false;
    const Scalar* countType = nullptr;
};
struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};
enum class Encoding { Ascii, LittleEndian, BigEndian };
struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    size_t dataStart = 0;
};

Header parseHeader(const std::string& bytes, const std::string& path) {
    Header h;
    bool haveFormat = false;
    size_t pos = 0;
    for (int lineNo = 1;; ++lineNo) {
        size_t end = bytes.find('\n', pos);
        if (end == std::string::npos) throw FormatError(path + ": the PLY header has no end_header line");
        std::istringstream line(bytes.substr(pos, end - pos));
        pos = end + 1;
        auto bad = [&](const std::string& why) {
            return FormatError(path + ": PLY header line " + std::to_string(lineNo) + ": " + why);
        };
        std::string key, a, b, c;
        line >> key;
        if (lineNo == 1) {
            if (key != "ply") throw bad("the file does not start with 'ply'");
        } else if (key == "format") {
            line >> a >> b;
            if (a == "ascii") h.encoding = Encoding::Ascii;
            else if (a == "binary_little_endian") h.encoding = Encoding::LittleEndian;
            else if (a == "binary_big_endian") h.encoding = Encoding::BigEndian;
            else throw bad("unknown format '" + a + "'");
            haveFormat = true;
        } else if (key == "element") {
            Element e;
            line >> e.name >> a;
            auto [p, ec] = std::from_chars(a.data(), a.data() + a.size(), e.count);
            if (e.name.empty() || ec != std::errc() || p != a.data() + a.size())
                throw bad("element needs a name and a count, not '" + a + "'");
            h.elements.push_back(e);
        } else if (key == "property") {
            if (h.elements.empty()) throw bad("property before any element");
            Property p;
            line >> a;
            if (a == "list") {
                p.isList = true;
                line >> b >> c >> p.name;
                p.countType = parseScalar(b);
                p.type = parseScalar(c);
                if (!p.countType || !p.type) throw bad("unknown list types");
            } else {
                line >> p.name;
                p.type = parseScalar(a);
                if (!p.type) throw bad("unknown property type '" + a + "'");
            }
            if (p.name.empty()) throw bad("property without a name");
            h.elements.back().properties.push_back(p);
        } else if (key == "end_header") {
            if (!haveFormat) throw bad("end_header before any format line");
            h.dataStart = pos;
            return h;
        } else if (key != "comment" && key != "obj_info" && !key.empty()) {
            throw bad("unknown keyword '" + key + "'");
        }
    }
}

// --- body values -----------------------------------------------------------------------
class Body {
public:
    Body(const std::string& bytes, size_t pos, Encoding encoding)
        : bytes_(bytes), pos_(pos), encoding_(encoding) {}

    // False at the end of the data or on a token that is not a number.
    bool read(const Scalar& type, double& value) {
        return encoding_ == Encoding::Ascii ? readAscii(value) : readBinary(type, value);
    }
    size_t remaining() const { return bytes_.size() - pos_; }

private:
    bool readAscii(double& value) {
        const char* s = bytes_.data();
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(s[pos_]))) ++pos_;
        size_t end = pos_;
        while (end < bytes_.size() && !std::isspace(static_cast<unsigned char>(s[end]))) ++end;
        if (end == pos_) return false;
        auto [p, ec] = std::from_chars(s + pos_, s + end, value);
        if (ec != std::errc() || p != s + end) return false;
        pos_ = end;
        return true;
    }

    // The bytes in the file's order, assembled as an unsigned value, then taken as the type.
    bool readBinary(const Scalar& type, double& value) {
        if (remaining() < type.size) return false;
        uint64_t u = 0;
        for (unsigned i = 0; i < type.size; ++i) {
            const size_t at = pos_ + (encoding_ == Encoding::BigEndian ? type.size - 1 - i : i);
            u |= uint64_t(static_cast<unsigned char>(bytes_[at])) << (8 * i);
        }
        pos_ += type.size;
        const unsigned bits = 8 * type.size;
        if (type.kind == 'f')
            value = type.size == 4 ? double(std::bit_cast<float>(uint32_t(u))) : std::bit_cast<double>(u);
        else if (type.kind == 'i' && u >> (bits - 1)) value = double(int64_t(u) - (int64_t(1) << bits));
        else value = double(u);
        return true;
    }

    const std::string& bytes_;
    size_t pos_;
    Encoding encoding_;
};

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

int indexOf(const Element& e, const char* name) {
    for (size_t i = 0; i < e.properties.size(); ++i)
        if (!e.properties[i].isList && e.properties[i].name == name) return int(i);
    return -1;
}

// Smallest size one item can have.
uint64_t minItemBytes(const Element& e, Encoding encoding) {
    uint64_t n = 0;
    for (const auto& p : e.properties)
        n += encoding == Encoding::Ascii ? 2 : (p.isList ? p.countType : p.type)->size;
    return n;
}

}  // namespace

// --- readPly ---------------------------------------------------------------------------
namespace {

struct Geometry {
    vtkSmartPointer<vtkPoints> points = vtkSmartPointer<vtkPoints>::New();
    vtkSmartPointer<vtkFloatArray> normals = vtkSmartPointer<vtkFloatArray>::New();
    vtkSmartPointer<vtkCellArray> polys = vtkSmartPointer<vtkCellArray>::New();
};

// Reads all items of `e`, keeping vertex positions/normals and face index lists.
void readElement(const Element& e, bool isVertex, Body& body, const std::string& path, Geometry& out) {
    const int xyz[3] = {indexOf(e, "x"), indexOf(e, "y"), indexOf(e, "z")};
    const int nxyz[3] = {indexOf(e, "nx"), indexOf(e, "ny"), indexOf(e, "nz")};
    const bool hasNormals = isVertex && nxyz[0] >= 0 && nxyz[1] >= 0 && nxyz[2] >= 0;
    std::vector<double> values(e.properties.size());
    std::vector<vtkIdType> ids;
    for (uint64_t item = 0; item < e.count; ++item) {
        auto fail = [&](const Property& p, const std::string& why) {
            return FormatError(path + ": PLY element '" + e.name + "' item " + std::to_string(item) + " of " +
                               std::to_string(e.count) + ", property '" + p.name + "': " + why);
        };
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (!p.isList) {
                if (!body.read(*p.type, values[k])) throw fail(p, "truncated or not a number");
                continue;
            }
            double count;
            if (!body.read(*p.countType, count)) throw fail(p, "truncated or not a number");
            if (count < 0 || count != std::floor(count) || count > double(body.remaining()))
                throw fail(p, "bad list length " + number(count));
            const bool keep = e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
            ids.clear();
            for (uint64_t i = 0; i < uint64_t(count); ++i) {
                double v;
                if (!body.read(*p.type, v)) throw fail(p, "truncated or not a number");
                if (keep && (v < 0 || v != std::floor(v) || v > 9.0e15)) throw fail(p, "bad vertex index " + number(v));
                if (keep) ids.push_back(static_cast<vtkIdType>(v));
            }
            if (keep && ids.size() >= 3) out.polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
        }
        if (isVertex) {
            out.points->InsertNextPoint(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
            if (hasNormals) out.normals->InsertNextTuple3(values[nxyz[0]], values[nxyz[1]], values[nxyz[2]]);
        }
    }
}

}  // namespace

vtkSmartPointer<vtkPolyData> readPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const Header header = parseHeader(bytes, path);

    auto vertex = std::find_if(header.elements.begin(), header.elements.end(),
                               [](const Element& e) { return e.name == "vertex"; });
    if (vertex == header.elements.end() || indexOf(*vertex, "x") < 0 || indexOf(*vertex, "y") < 0 ||
        indexOf(*vertex, "z") < 0)
        throw FormatError(path + ": the PLY file has no vertex element with x, y, z properties");

    Geometry geometry;
    geometry.normals->SetName("Normals");
    geometry.normals->SetNumberOfComponents(3);
    Body body(bytes, header.dataStart, header.encoding);
    for (const Element& e : header.elements) {
        // An element without properties holds no bytes, whatever its count: nothing to read
        // (looping over a count of 2^64 - 1 empty items would hang).
        if (e.properties.empty()) continue;
        // A count the rest of the file cannot hold is refused before anything is allocated.
        const uint64_t need = minItemBytes(e, header.encoding);
        if (need > 0 && e.count > body.remaining() / need)
            throw FormatError(path + ": truncated PLY: the header declares " + std::to_string(e.count) + " '" +
                              e.name + "' items, more than the rest of the file can hold");
        readElement(e, &e == &*vertex, body, path, geometry);
    }

    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(geometry.points);
    poly->SetPolys(geometry.polys);
    if (geometry.normals->GetNumberOfTuples() > 0) poly->GetPointData()->SetNormals(geometry.normals);
    return poly;
}

}  // namespace flowsurf::io::detail
