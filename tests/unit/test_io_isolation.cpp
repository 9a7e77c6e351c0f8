// Files are read in a child process (src/io/reader_process.h): whatever happens to the
// child — a crash, an abort, a hang, an allocation beyond its limit — the caller gets a
// one-line FormatError naming the file, and the next read works. A stand-in reader
// (a shell script through FLOWSURF_READER) plays the misbehaving child.
#include "core/errors.h"
#include "core/time_series.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"

#include "test_io_common.h"

#include <sys/stat.h>

#include <cstdlib>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

std::string script(const ScratchDir& dir, const std::string& body) {
    const std::string path = dir.file("reader.sh");
    writeText(path, "#!/bin/sh\n" + body + "\n");
    chmod(path.c_str(), 0755);
    return path;
}

std::string validPly(const ScratchDir& dir) {
    const std::string path = dir.file("tri.ply");
    writeText(path, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    return path;
}

}  // namespace

TEST(IoIsolation, CrashingReaderIsAOneLineFormatErrorNamingTheFile) {
    ScratchDir dir;
    const std::string file = validPly(dir);
    for (const char* sig : {"SEGV", "ABRT", "BUS"}) {
        ScopedEnv env("FLOWSURF_READER", script(dir, std::string("kill -") + sig + " $$"));
        std::string what = formatErrorOf(file);
        EXPECT_NE(what.find(file), std::string::npos) << what;
        EXPECT_NE(what.find(std::string("SIG") + sig), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(IoIsolation, HangingReaderTimesOut) {
    ScratchDir dir;
    const std::string file = validPly(dir);
    ScopedEnv reader("FLOWSURF_READER", script(dir, "exec sleep 30"));
    ScopedEnv timeout("FLOWSURF_READER_TIMEOUT_S", "1");
    std::string what = formatErrorOf(file);
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find("took longer than 1 s"), std::string::npos) << what;
}

TEST(IoIsolation, ReaderOverItsMemoryLimitIsAFormatError) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "no address-space limit under AddressSanitizer";
#endif
    ScratchDir dir;
    const std::string file = validPly(dir);
    {
        ScopedEnv memory("FLOWSURF_READER_MEMORY_MB", "16");  // not even VTK's libraries fit
        std::string what = formatErrorOf(file);
        EXPECT_NE(what.find(file), std::string::npos) << what;
    }
    EXPECT_EQ(io::readDataset(file).steps.at(0).mesh.triangleCount(), 1u) << "the limit is per child";
}

TEST(IoIsolation, SeriesReadsEveryFileThroughOneReader) {
    ScratchDir dir;
    for (int i = 0; i < 3; ++i) {
        const std::string p = validPly(dir);
        std::filesystem::rename(p, dir.file("s_" + std::to_string(i) + ".ply"));
    }
    auto series = io::openSeries(dir.file("s_%d.ply"));
    ASSERT_EQ(series->count(), 3u);
    EXPECT_EQ(series->load(0).triangleCount(), 1u);
    EXPECT_EQ(series->load(2).triangleCount(), 1u);
}

// A series whose middle step makes VTK's reader loop until its CPU limit ends it: that step
// is an error naming the collection, and the next one is read by a fresh child that
// re-opened the collection.
TEST(IoIsolation, StepAfterOneThatEndedTheReaderIsReadByAFreshOne) {
    ScratchDir dir;
    for (const char* name : {"a.ply", "c.ply"}) std::filesystem::rename(validPly(dir), dir.file(name));
    // An EnSight nsided block whose second element's line is missing: VTK 9.1 waits for it.
    writeText(dir.file("b.case"), "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: b.geo\n");
    writeText(dir.file("b.geo"), "x\ny\nnode id off\nelement id off\npart\n1\ns\ncoordinates\n4\n0\n1\n1\n0\n"
                                 "0\n0\n1\n1\n0\n0\n0\n0\nnsided\n2\n4\n4\n1 2 3 4\n#\n");
    writeText(dir.file("s.pvd"), "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" file=\"a.ply\"/>"
                                 "<DataSet timestep=\"1\" file=\"b.case\"/><DataSet timestep=\"2\" file=\"c.ply\"/>"
                                 "</Collection></VTKFile>");
    auto series = io::openSeries(dir.file("s.pvd"));
    ASSERT_EQ(series->count(), 3u);
    EXPECT_EQ(series->load(0).triangleCount(), 1u);
    try {
        series->load(1);
        ADD_FAILURE() << "step 2 read";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find(dir.file("s.pvd")), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(": the reader "), std::string::npos) << e.what();  // it ended
    }
    EXPECT_EQ(series->load(2).triangleCount(), 1u);
}
