#include "io/reader/xml_check.h"

#include "core/errors.h"

#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

namespace flowsurf::io::detail {

namespace {

int base64Value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

// The first `count` bytes at `pos`, raw or base64-decoded (whitespace skipped, as
// inline data starts on a new line). Empty if the file ends first.
std::string headerBytes(std::istream& in, int64_t pos, size_t count, bool base64) {
    in.clear();
    in.seekg(pos);
    std::string out;
    if (!base64) {
        out.resize(count);
        in.read(out.data(), std::streamsize(count));
        return in.gcount() == std::streamsize(count) ? out : std::string();
    }
    uint32_t bits = 0;
    int nbits = 0;
    char c;
    while (out.size() < count && in.get(c)) {
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        int v = base64Value(c);
        if (v < 0) return {};
        bits = (bits << 6) | uint32_t(v);
        nbits += 6;
        if (nbits >= 8) {
            nbits -= 8;
            out.push_back(char((bits >> nbits) & 0xFF));
        }
    }
    return out.size() == count ? out : std::string();
}

void forEachElement(vtkXMLDataElement* e, const std::function<void(vtkXMLDataElement*)>& visit) {
    visit(e);
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i) forEachElement(e->GetNestedElement(i), visit);
}

int64_t intAttribute(vtkXMLDataElement* e, const char* name, int64_t fallback) {
    const char* v = e ? e->GetAttribute(name) : nullptr;
    return v ? std::strtoll(v, nullptr, 10) : fallback;
}

uint64_t wordSize(const char* type) {
    static const std::pair<const char*, uint64_t> kSizes[] = {
        {"Int8", 1}, {"UInt8", 1}, {"Int16", 2}, {"UInt16", 2}, {"Int32", 4},
        {"UInt32", 4}, {"Float32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float64", 8}};
    for (const auto& [n, size] : kSizes)
        if (type && std::strcmp(type, n) == 0) return size;
    return 0;
}

// The fewest values an array must hold, from its place in the piece (0: unknown).
// VTK trusts the block table to cover them and reads past it otherwise.
uint64_t minimumWords(vtkXMLDataElement* e) {
    const int64_t components = std::max<int64_t>(1, intAttribute(e, "NumberOfComponents", 1));
    if (e->GetAttribute("NumberOfTuples")) return uint64_t(std::max<int64_t>(0, intAttribute(e, "NumberOfTuples", 0) * components));
    vtkXMLDataElement* parent = e->GetParent();
    vtkXMLDataElement* piece = parent ? parent->GetParent() : nullptr;
    if (!piece || std::strcmp(piece->GetName(), "Piece") != 0) return 0;
    const std::string group = parent->GetName();
    const std::string name = e->GetAttribute("Name") ? e->GetAttribute("Name") : "";
    int64_t cells = intAttribute(piece, "NumberOfCells", 0);
    for (const char* kind : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        cells += intAttribute(piece, kind, 0);
    int64_t count = 0;
    if (group == "PointData" || group == "Points") count = intAttribute(piece, "NumberOfPoints", 0) * components;
    else if (group == "CellData") count = cells * components;
    else if (group == "Cells" && (name == "offsets" || name == "types" || name == "connectivity"))
        count = intAttribute(piece, "NumberOfCells", 0);  // connectivity: at least one point per cell
    else if (group == "Verts" || group == "Lines" || group == "Strips" || group == "Polys")
        count = intAttribute(piece, ("NumberOf" + group).c_str(), 0);
    return uint64_t(std::max<int64_t>(0, count));
}

// How the file stores compressed arrays (from the root and AppendedData elements).
struct Layout {
    size_t headerSize = 4;  // header_type UInt32 or UInt64
    bool bigEndian = false;
    bool appendedBase64 = true;
    int64_t appendedStart = 0;
    uint64_t fileSize = 0;
};

uint64_t saturatingMul(uint64_t a, uint64_t b) {
    uint64_t r;
    return __builtin_mul_overflow(a, b, &r) ? ~uint64_t(0) : r;
}

// Header: block count, block size, last block size, compressed size of each block.
void checkArray(vtkXMLDataElement* e, const Layout& layout, std::ifstream& in, const std::string& path) {
    const char* format = e->GetAttribute("format");
    int64_t pos;
    bool base64 = true;
    if (std::strcmp(format, "appended") == 0) {
        pos = layout.appendedStart + intAttribute(e, "offset", 0);
        base64 = layout.appendedBase64;
    } else if (std::strcmp(format, "binary") == 0) {
        // Inline data starts after the start tag's '>' (as vtkXMLDataParser finds it).
        in.clear();
        in.seekg(e->GetXMLByteIndex());
        in.ignore(std::numeric_limits<std::streamsize>::max(), '>');
        pos = in.tellg();
    } else {
        return;  // ascii
    }
    const char* name = e->GetAttribute("Name");
    const std::string what = path + ": compressed array '" + (name ? name : "?") + "'";
    const size_t h = layout.headerSize;
    auto headerInt = [&](const std::string& bytes, size_t i) {
        uint64_t v = 0;
        for (size_t b = 0; b < h; ++b)
            v = (v << 8) | static_cast<unsigned char>(bytes[i * h + (layout.bigEndian ? b : h - 1 - b)]);
        return v;
    };
    std::string bytes = headerBytes(in, pos, h, base64);
    if (bytes.empty()) throw FormatError(what + " has a truncated or unreadable header");
    const uint64_t blocks = headerInt(bytes, 0);
    if (blocks + 3 > layout.fileSize / h)
        throw FormatError(what + " declares " + std::to_string(blocks) +
                          " blocks, more than the file can hold (corrupt header)");
    bytes = headerBytes(in, pos, h * (3 + blocks), base64);
    if (bytes.empty()) throw FormatError(what + " has a truncated header");
    const uint64_t blockSize = headerInt(bytes, 1), lastSize = headerInt(bytes, 2);
    uint64_t compressed = 0;
    for (uint64_t b = 0; b < blocks && compressed <= layout.fileSize; ++b) compressed += headerInt(bytes, 3 + b);
    const uint64_t room = layout.fileSize - std::min<uint64_t>(layout.fileSize, uint64_t(pos));
    if ((blocks > 0 && (blockSize == 0 || lastSize > blockSize)) || compressed > room)
        throw FormatError(what + " has an inconsistent block table (corrupt header)");
    const uint64_t total = blocks == 0 ? 0 : saturatingMul(blocks - 1, blockSize) + (lastSize ? lastSize : blockSize);
    const uint64_t need = saturatingMul(minimumWords(e), wordSize(e->GetAttribute("type")));
    if (total < need)
        throw FormatError(what + " holds " + std::to_string(total) + " bytes, at least " + std::to_string(need) +
                          " needed (corrupt header)");
}

}  // namespace

void checkXmlCompressionHeaders(const std::string& path) {
    auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
    parser->SetFileName(path.c_str());
    parser->SetIgnoreCharacterData(1);
    if (!parser->Parse()) return;
    vtkXMLDataElement* root = parser->GetRootElement();
    const char* compressor = root ? root->GetAttribute("compressor") : nullptr;
    if (!compressor || !*compressor) return;
    Layout layout;
    const char* headerType = root->GetAttribute("header_type");
    layout.headerSize = headerType && std::strcmp(headerType, "UInt64") == 0 ? 8 : 4;
    const char* byteOrder = root->GetAttribute("byte_order");
    layout.bigEndian = byteOrder && std::strcmp(byteOrder, "BigEndian") == 0;
    vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
    const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
    layout.appendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
    layout.appendedStart = parser->GetAppendedDataPosition();
    layout.fileSize = std::filesystem::file_size(path);
    std::ifstream in(path, std::ios::binary);
    forEachElement(root, [&](vtkXMLDataElement* e) {
        const char* element = e->GetName();
        if (e->GetAttribute("format") && (std::strcmp(element, "DataArray") == 0 || std::strcmp(element, "Array") == 0))
            checkArray(e, layout, in, path);
    });
}

}  // namespace flowsurf::io::detail
