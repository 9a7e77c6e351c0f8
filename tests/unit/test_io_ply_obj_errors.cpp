// Bad input to flowsurf's own PLY and OBJ parsers (io/reader/parsers.h): each case is a
// FormatError naming the file and what is wrong (for OBJ the line), and every PLY scalar
// type decodes in both byte orders.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/parsers.h"

#include "test_io_common.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

using namespace flowsurf;
using namespace flowsurf::testing_io;

TEST(IoReaders, MalformedPlyHeadersAreFormatErrors) {
    ScratchDir dir;
    const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
    const std::pair<std::string, std::string> cases[] = {
        {"ply\nformat weird 1.0\nelement vertex 1\n" + xyz + "end_header\n0 0 0\n", "unknown format"},
        {"ply\nformat ascii 1.0\nelement vertex 9\nend_header\n1 2\n", "x, y, z"},
        {"ply\nformat ascii 1.0\nelement vertex 4\n" + xyz, "no end_header"},
        {"ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n", "before any element"},
        {"ply\nformat ascii 1.0\nelement vertex -5\n" + xyz + "end_header\n", "count"},
        {"ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
             "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n",
         "list length"},
        {"ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "end_header\nA B C\n", "not a number"},
    };
    int i = 0;
    for (const auto& [text, why] : cases) {
        const std::string name = "bad" + std::to_string(i++) + ".ply";
        writeText(dir.file(name), text);
        expectReadError<FormatError>(dir.file(name), name, why);
    }
}

// Found by fuzz_ply: an element with no properties and a count of 2^64 - 1 held the reader
// in a loop over empty items. Such an element holds no bytes; the file reads at once.
TEST(IoReaders, PlyElementWithoutPropertiesAndHugeCountReadsAtOnce) {
    ScratchDir dir;
    writeText(dir.file("empty_element.ply"),
              "ply\nformat ascii 1.0\nelement junk 18446744073709551615\n"
              "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const auto poly = io::detail::readPly(dir.file("empty_element.ply"));
    EXPECT_EQ(poly->GetNumberOfPoints(), 3);
    EXPECT_EQ(poly->GetNumberOfPolys(), 1);
}

// Binary PLY in both byte orders: signed, unsigned and floating-point types decode to the
// values written (the host's bytes, reversed for big-endian).
TEST(IoReaders, BinaryPlyDecodesEveryScalarTypeInBothByteOrders) {
    ScratchDir dir;
    const int8_t x[3] = {-3, 0, 5};
    const int16_t y[3] = {-300, 2, 7};
    const double z[3] = {-0.5, 1.25, 1e10};
    const float nz = -1.0f;
    const uint32_t extra = 4000000000u;
    for (const char* order : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(order);
        std::string body;
        const auto put = [&](const void* p, size_t n) {
            std::string bytes(static_cast<const char*>(p), n);
            if (order[7] == 'b') std::reverse(bytes.begin(), bytes.end());
            body += bytes;
        };
        for (int i = 0; i < 3; ++i) {
            put(&x[i], 1), put(&y[i], 2), put(&z[i], 8), put(&extra, 4);
            for (float n : {0.0f, 0.0f, nz}) put(&n, 4);
        }
        const uint16_t corners = 3;
        put(&corners, 2);
        for (int32_t id : {2, 1, 0}) put(&id, 4);
        writeText(dir.file("binary.ply"), std::string("ply\nformat ") + order +
                                              " 1.0\nelement vertex 3\nproperty char x\nproperty int16 y\n"
                                              "property float64 z\nproperty uint extra\nproperty float nx\n"
                                              "property float ny\nproperty float32 nz\nelement face 1\n"
                                              "property list ushort int vertex_indices\nend_header\n" + body);
        const auto poly = io::detail::readPly(dir.file("binary.ply"));
        ASSERT_EQ(poly->GetNumberOfPoints(), 3);
        for (int i = 0; i < 3; ++i) {
            double p[3];
            poly->GetPoint(i, p);
            EXPECT_EQ(p[0], x[i]);
            EXPECT_EQ(p[1], y[i]);
            EXPECT_EQ(p[2], z[i]);
            EXPECT_EQ(poly->GetPointData()->GetNormals()->GetComponent(i, 2), nz);
        }
        vtkIdType n;
        const vtkIdType* ids;
        poly->GetPolys()->InitTraversal();
        ASSERT_TRUE(poly->GetPolys()->GetNextCell(n, ids));
        EXPECT_EQ(n, 3);
        EXPECT_EQ(ids[0], 2);
    }
}

TEST(IoReaders, MalformedObjNamesTheLine) {
    ScratchDir dir;
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::pair<std::string, std::string> cases[] = {
        {tri + "f 1 2 99\n", "line 4: vertex index 99 is out of range"},
        {tri + "f 0 1 2\n", "line 4: vertex index 0"},
        {tri + "f -1 -2 -9\n", "line 4: vertex index -9"},
        {tri + "f 1 2\n", "at least 3 vertices"},
        {"v 0 0 0\nv 1 0\n", "line 2: a vertex needs three numbers"},
        {"v a b c\n", "line 1"},
        {tri + "f 1 x 3\n", "'x' is not a vertex index"},
    };
    int i = 0;
    for (const auto& [text, why] : cases) {
        const std::string name = "bad" + std::to_string(i++) + ".obj";
        writeText(dir.file(name), text);
        expectReadError<FormatError>(dir.file(name), name, why);
    }
    // Texture and normal references are ignored, even dangling ones (VTK 9.1 crashed).
    writeText(dir.file("refs.obj"), tri + "vt 0 0\nf 1/1 2/7/3 -1//9\n");
    EXPECT_EQ(io::readDataset(dir.file("refs.obj")).steps[0].mesh.triangleCount(), 1u);
}
