// EnSight Gold cases whose counts exceed their files kept VTK's reader looping until the
// reader's timeout (minutes for a 1 KB file): they are refused before VTK sees them
// (src/io/reader/ensight_check.h), with the file and the count in the message, while
// valid ASCII and C binary cases (either byte order, ids listed or not, a time series of
// geometry files) still read. The reader's time budget follows the input's size.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/reader_process.h"

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

// A hang would show as "took longer than 20 s" instead of the check's message.
std::string refusal(const std::string& path) {
    ScopedEnv budget("FLOWSURF_READER_TIMEOUT_S", "20");
    return formatErrorOf(path);
}

void expectRefused(const std::string& what, const std::string& file, const std::string& count) {
    EXPECT_NE(what.find(file + ": EnSight"), std::string::npos) << what;
    EXPECT_NE(what.find("declares " + count), std::string::npos) << what;
    EXPECT_EQ(what.find("took longer"), std::string::npos) << what;
}

}  // namespace

TEST(IoEnSight, AsciiCountsBeyondTheFileAreRefusedNamingFileAndCount) {
    ScratchDir dir;
    const std::string geo = dir.file("mesh.geo"), path = caseFile(dir, "mesh.geo");
    const std::pair<std::string, std::string> cases[] = {
        // VTK 9.1 allocates for these and loops at the end of the file past any timeout.
        {asciiSquare("100000000"), "100000000 nodes"},
        {asciiSquare("4", "50000000"), "50000000 elements"},
        {asciiSquare("4", "900"), "900 elements"},  // beyond the lines left, not the bytes
        {asciiSquare("-4"), ""},                    // no count is negative
    };
    for (const auto& [text, count] : cases) {
        writeText(geo, text);
        const std::string what = refusal(path);
        if (count.empty()) EXPECT_NE(what.find(geo + ": EnSight count '-4' is negative"), std::string::npos) << what;
        else expectRefused(what, geo, count);
    }
}

TEST(IoEnSight, NsidedConnectivityMissingIsRefused) {
    // VTK waits for the missing line of an nsided block forever; comment lines are not data.
    ScratchDir dir;
    const std::string geo = dir.file("mesh.geo");
    std::string text = asciiSquare();
    text = text.substr(0, text.find("tria3")) + "nsided\n2\n4\n4\n         1         2         3         4\n#\n\n";
    writeText(geo, text);
    const std::string what = refusal(caseFile(dir, "mesh.geo"));
    expectRefused(what, geo, "2 elements");
    EXPECT_NE(what.find("the file ends after 1"), std::string::npos) << what;
}

TEST(IoEnSight, BinaryCountsBeyondTheFileAreRefusedInEitherByteOrder) {
    ScratchDir dir;
    const std::string geo = dir.file("mesh.geo"), path = caseFile(dir, "mesh.geo");
    for (bool big : {false, true}) {
        writeText(geo, binarySquare(big, 1 << 30));
        expectRefused(refusal(path), geo, std::to_string(1 << 30) + " nodes");
        writeText(geo, binarySquare(big, 4, 5000));
        expectRefused(refusal(path), geo, "5000 elements");
    }
}

TEST(IoEnSight, StepCountBeyondTheCaseFileIsRefused) {
    ScratchDir dir;
    writeText(dir.file("mesh.geo"), asciiSquare());
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 mesh.geo\nTIME\ntime set: 1\n"
                    "number of steps: 1000000000\ntime values: 0\n");
    const std::string what = refusal(path);
    EXPECT_NE(what.find(path + ": EnSight 'number of steps' declares 1000000000 steps"), std::string::npos) << what;
}

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

TEST(IoEnSight, EveryGeometryFileOfASeriesIsChecked) {
    ScratchDir dir;
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 mesh.geo**\nTIME\ntime set: 1\n"
                    "number of steps: 3\nfilename start number: 0\nfilename increment: 2\ntime values: 0 1 2\n");
    for (const char* step : {"00", "02", "04"})
        writeText(dir.file(std::string("mesh.geo") + step), binarySquare(false));
    core::Dataset ds = io::readDataset(path);
    ASSERT_EQ(ds.steps.size(), 3u);
    EXPECT_EQ(ds.steps[2].mesh.triangleCount(), 2u);
    // The last step's file is the bad one: refused when the case is opened.
    writeText(dir.file("mesh.geo04"), binarySquare(false, 4, 70000));
    expectRefused(refusal(path), dir.file("mesh.geo04"), "70000 elements");
}

// The budgets: the base for an empty input, more per MiB (time rounded up to whole
// seconds), a real 1 GiB case well beyond what the slowest reader needs (8 MB/s measured:
// about 130 s), and capped.
TEST(IoReaderBudget, GrowsWithTheInputSize) {
    using io::detail::readerBudget;
    EXPECT_EQ(readerBudget(0).wallS, 30);
    EXPECT_EQ(readerBudget(0).cpuS, 2);
    EXPECT_EQ(readerBudget(0).memoryMb, 2048u);
    EXPECT_EQ(readerBudget(1024).wallS, 31);
    EXPECT_EQ(readerBudget(1024).cpuS, 2);  // CPU time: to the nearest second
    EXPECT_EQ(readerBudget(100ull << 20).wallS, 80);
    EXPECT_EQ(readerBudget(100ull << 20).cpuS, 102);
    EXPECT_EQ(readerBudget(1600ull << 10).cpuS, 4);
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
