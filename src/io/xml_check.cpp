#include "io/xml_check.h"

#include "core/errors.h"

#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

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

}  // namespace

void checkXmlCompressionHeaders(const std::string& path) {
    auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
    parser->SetFileName(path.c_str());
    parser->SetIgnoreCharacterData(1);
    if (!parser->Parse()) return;
    vtkXMLDataElement* root = parser->GetRootElement();
    const char* compressor = root ? root->GetAttribute("compressor") : nullptr;
    if (!compressor || !*compressor) return;
    const char* headerType = root->GetAttribute("header_type");
    const size_t headerSize = headerType && std::strcmp(headerType, "UInt64") == 0 ? 8 : 4;
    const char* byteOrder = root->GetAttribute("byte_order");
    const bool bigEndian = byteOrder && std::strcmp(byteOrder, "BigEndian") == 0;
    vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
    const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
    const bool appendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
    const uint64_t fileSize = std::filesystem::file_size(path);
    std::ifstream in(path, std::ios::binary);

    forEachElement(root, [&](vtkXMLDataElement* e) {
        const char* format = e->GetAttribute("format");
        if (!format || (std::strcmp(e->GetName(), "DataArray") != 0 && std::strcmp(e->GetName(), "Array") != 0))
            return;
        int64_t pos;
        bool base64;
        if (std::strcmp(format, "appended") == 0) {
            const char* offset = e->GetAttribute("offset");
            pos = parser->GetAppendedDataPosition() + (offset ? std::strtoll(offset, nullptr, 10) : 0);
            base64 = appendedBase64;
        } else if (std::strcmp(format, "binary") == 0) {
            // Inline data starts after the start tag's '>' (as vtkXMLDataParser finds it).
            in.clear();
            in.seekg(e->GetXMLByteIndex());
            in.ignore(std::numeric_limits<std::streamsize>::max(), '>');
            pos = in.tellg();
            base64 = true;
        } else {
            return;
        }
        const char* name = e->GetAttribute("Name");
        const std::string what = path + ": compressed array '" + (name ? name : "?") + "'";
        // The header's first integer is the block count.
        const std::string bytes = headerBytes(in, pos, headerSize, base64);
        if (bytes.empty()) throw FormatError(what + " has a truncated or unreadable header");
        uint64_t blocks = 0;
        for (size_t i = 0; i < headerSize; ++i) {
            const size_t k = bigEndian ? i : headerSize - 1 - i;
            blocks = (blocks << 8) | static_cast<unsigned char>(bytes[k]);
        }
        if (blocks > fileSize / headerSize)
            throw FormatError(what + " declares " + std::to_string(blocks) +
                              " blocks, more than the file can hold (corrupt header)");
    });
}

}  // namespace flowsurf::io::detail
