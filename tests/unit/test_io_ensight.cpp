// EnSight Gold cases read in ASCII and C binary (either byte order, ids listed or not, a
// time series of geometry files); hostile ones are in test_io_hostile_files.cpp. The
// reader process's budgets follow the input's size.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader_process.h"

#include "test_io_common.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {


std::string caseFile(const ScratchDir& dir, const std::string& geometry, const std::string& model = "") {
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: " + (model.empty() ? geometry : model) + "\n");
    return path;
}

// The unit square as two triangles, one value per line; `coordinates`/`elements` replace
// the counts (the data stays the same), `ids` lists node and element ids.
std::string asciiSquare(const std::string& coordinates = "4", const std::string& elements = "2", bool ids = false) {
    std::string s = "square\ngeometry\nnode id " + std::string(ids ? "given" : "off") + "\nelement id " +
                    (ids ? "given" : "off") + "\npart\n         1\nsquare\ncoordinates\n" + coordinates + "\n";
    if (ids) s += "11\n12\n13\n14\n";
    for (const char* v : {"0", "1", "1", "0", "0", "0", "1", "1", "0", "0", "0", "0"}) s += std::string(v) + "\n";
    s += "tria3\n" + elements + "\n";
    if (ids) s += "7\n8\n";
    return s + "         1         2         3\n         1         3         4\n";
}

// The same square in C binary, in either byte order; `coordinates`/`elements` replace
// the counts.
class Binary {
public:
    explicit Binary(bool bigEndian) : big_(bigEndian) {}
    Binary& str(const std::string& s) {
        std::string field = s;
        field.resize(80, '\0');
        bytes_ += field;
        return *this;
    }
    Binary& i32(int32_t v) {
        uint32_t u;
        std::memcpy(&u, &v, 4);
        for (int i = 0; i < 4; ++i) bytes_ += char(u >> (8 * (big_ ? 3 - i : i)));
        return *this;
    }
    Binary& f32(float v) {
        int32_t i;
        std::memcpy(&i, &v, 4);
        return i32(i);
    }
    const std::string& bytes() const { return bytes_; }

private:
    bool big_;
    std::string bytes_;
};

std::string binarySquare(bool bigEndian, int32_t coordinates = 4, int32_t elements = 2) {
    Binary b(bigEndian);
    b.str("C Binary").str("square").str("geometry").str("node id off").str("element id off");
    b.str("part").i32(1).str("square").str("coordinates").i32(coordinates);
    for (float v : {0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0}) b.f32(v);
    b.str("tria3").i32(elements);
    for (int32_t v : {1, 2, 3, 1, 3, 4}) b.i32(v);
    return b.bytes();
}

}  // namespace

TEST(IoEnSight, ValidAsciiAndBinaryCasesRead) {
    ScratchDir dir;
    const std::string geo = dir.file("mesh.geo"), path = caseFile(dir, "mesh.geo");
    const std::pair<std::string, std::string> cases[] = {
        {asciiSquare(), "ASCII"},
        {asciiSquare("4", "2", true), "ASCII with ids"},
        {binarySquare(false), "little-endian"},
        {binarySquare(true), "big-endian"},
    };
    for (const auto& [text, name] : cases) {
        writeText(geo, text);
        core::Dataset ds = io::readDataset(path);
        ASSERT_EQ(ds.steps.size(), 1u) << name;
        EXPECT_EQ(ds.steps[0].mesh.triangleCount(), 2u) << name;
        EXPECT_EQ(ds.steps[0].mesh.vertexCount(), 4u) << name;
    }
}

TEST(IoEnSight, SeriesOfGeometryFilesReads) {
    ScratchDir dir;
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 mesh.geo**\nTIME\ntime set: 1\n"
                    "number of steps: 3\nfilename start number: 0\nfilename increment: 2\ntime values: 0 1 2\n");
    for (const char* step : {"00", "02", "04"})
        writeText(dir.file(std::string("mesh.geo") + step), binarySquare(false));
    core::Dataset ds = io::readDataset(path);
    ASSERT_EQ(ds.steps.size(), 3u);
    EXPECT_EQ(ds.steps[2].mesh.triangleCount(), 2u);
}

// The budgets: the base for an empty input, more per MiB (time rounded up to whole
// seconds), a real 1 GiB case well beyond what the slowest reader needs (8 MB/s measured:
// about 130 s), and capped.
TEST(IoReaderBudget, GrowsWithTheInputSize) {
    using io::detail::readerBudget;
    EXPECT_EQ(readerBudget(0).wallS, 30);
    EXPECT_EQ(readerBudget(0).cpuS, 1);
    EXPECT_EQ(readerBudget(0).memoryMb, 2048u);
    EXPECT_EQ(readerBudget(1024).wallS, 31);
    EXPECT_EQ(readerBudget(1024).cpuS, 1);  // CPU time: to the nearest second
    EXPECT_EQ(readerBudget(100ull << 20).wallS, 80);
    EXPECT_EQ(readerBudget(100ull << 20).cpuS, 101);
    EXPECT_EQ(readerBudget(1600ull << 10).cpuS, 3);
    EXPECT_EQ(readerBudget(100ull << 20).memoryMb, 2048u + 3200u);
    EXPECT_EQ(readerBudget(1ull << 30).wallS, 30 + 512);
    EXPECT_EQ(readerBudget(~0ull).wallS, 7 * 24 * 3600);
    EXPECT_EQ(readerBudget(~0ull).cpuS, 7 * 24 * 3600);
}

TEST(IoReaderBudget, InputOfACaseIsItsFolder) {
    ScratchDir dir;
    writeText(dir.file("mesh.geo"), std::string(3000, 'x'));
    writeText(dir.file("t.case"), std::string(100, 'y'));
    fs::create_directories(dir.path() / "sub");
    writeText((dir.path() / "sub" / "U.0001").string(), std::string(500, 'z'));
    EXPECT_EQ(io::detail::readerInputBytes(dir.file("t.case")), 3600u);
    EXPECT_EQ(io::detail::readerInputBytes(dir.file("mesh.geo")), 3000u);  // one file, one size
}
