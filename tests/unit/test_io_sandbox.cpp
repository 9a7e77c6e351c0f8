// The reader's sandbox (src/io/reader/sandbox.h, doc/reader_sandbox.md): a reader that
// misbehaves after starting as flowsurf-reader does (tests/sandbox/hostile_reader.cpp,
// through FLOWSURF_READER) is stopped, and the caller's FormatError names the file and
// says what was hit; nothing is written.
#include "core/errors.h"
#include "io/dataset_reader.h"

#include "test_io_common.h"

#include <linux/landlock.h>
#include <sys/syscall.h>
#include <unistd.h>


using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// The message of reading a small file with the hostile reader doing `what`.
std::string refusal(const ScratchDir& dir, const char* what) {
    const std::string file = dir.file("in.ply");
    writeText(file, "ply\n");
    ScopedEnv reader("FLOWSURF_READER", FLOWSURF_HOSTILE_READER);
    ScopedEnv hostile("FLOWSURF_TEST_HOSTILE", what);
    const std::string message = formatErrorOf(file);
    EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
    return message;
}

}  // namespace

TEST(IoSandbox, ReaderOpeningANetworkSocketIsStopped) {
    ScratchDir dir;
    const std::string what = refusal(dir, "socket");
    EXPECT_NE(what.find("was stopped by its sandbox: it tried to open a network socket (socket)"), std::string::npos)
        << what;
}

TEST(IoSandbox, ReaderWritingAFileIsStoppedAndWritesNothing) {
    ScratchDir dir;
    const std::string what = refusal(dir, "write");
    EXPECT_NE(what.find("tried to open a file for writing (open"), std::string::npos) << what;
    EXPECT_EQ(dir.list(), std::vector<std::string>{"in.ply"});
}

TEST(IoSandbox, ReaderStartingAProgramOrProcessIsStopped) {
    ScratchDir dir;
    if (kSanitized) {  // answered EPERM under AddressSanitizer (its symbolizer)
        EXPECT_NE(refusal(dir, "exec").find("was not stopped: Operation not permitted"), std::string::npos);
        EXPECT_NE(refusal(dir, "fork").find("was not stopped: Operation not permitted"), std::string::npos);
        return;
    }
    std::string what = refusal(dir, "exec");
    EXPECT_NE(what.find("tried to run a program (execve)"), std::string::npos) << what;
    what = refusal(dir, "fork");
    EXPECT_NE(what.find("tried to start a process (clone)"), std::string::npos) << what;
}

TEST(IoSandbox, ReaderSignallingItsParentIsStopped) {
    ScratchDir dir;
    const std::string what = refusal(dir, "signal");
    EXPECT_NE(what.find("tried to reach another process (kill)"), std::string::npos) << what;
}

TEST(IoSandbox, ReaderSeesNothingOutsideTheInputsFolder) {
    if (syscall(__NR_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION) < 1)
        GTEST_SKIP() << "no Landlock in this kernel";
    ScratchDir dir;
    const std::string what = refusal(dir, "outside");
    EXPECT_NE(what.find("outside was not stopped: Permission denied"), std::string::npos) << what;
}

// The real reader: a collection naming a file outside its folder cannot read it, and says why.
TEST(IoSandbox, CollectionNamingAFileOutsideItsFolderSaysWhyItCannotBeRead) {
    if (syscall(__NR_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION) < 1)
        GTEST_SKIP() << "no Landlock in this kernel";
    ScratchDir dir;
    writeText(dir.file("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    fs::create_directories(dir.path() / "sub");
    const std::string pvd = (dir.path() / "sub" / "s.pvd").string();
    writeText(pvd, "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" file=\"../tri.obj\"/>"
                   "</Collection></VTKFile>");
    try {
        io::readDataset(pvd);
        ADD_FAILURE() << "read";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(pvd + ": "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Permission denied; the reader may read only below " +
                                             fs::weakly_canonical(dir.path() / "sub").string()),
                  std::string::npos)
            << e.what();
    }
    ScopedEnv off("FLOWSURF_READER_SANDBOX", "off");
    EXPECT_EQ(io::readDataset(pvd).steps.at(0).mesh.triangleCount(), 1u);
}

TEST(IoSandbox, SpinningReaderIsStoppedByItsCpuLimitWithinSeconds) {
    ScratchDir dir;
    std::string what;
    const Took took = timed([&] { what = refusal(dir, "spin"); });
    EXPECT_NE(what.find("used more than 1 s of CPU (its limit for this input's size; FLOWSURF_READER_TIMEOUT_S"),
              std::string::npos)
        << what;
    EXPECT_LT(took.cpu, 2.5);  // 1 s, and what the child used before the request rounded up
}

TEST(IoSandbox, ReaderOverItsMemoryLimitSaysHowMuch) {
    if (kSanitized) GTEST_SKIP() << "no address-space limit under AddressSanitizer";
    ScratchDir dir;
    ScopedEnv memory("FLOWSURF_READER_MEMORY_MB", "600");
    const std::string what = refusal(dir, "memory");
    EXPECT_NE(what.find("needed more than 600 MiB"), std::string::npos) << what;
}

TEST(IoSandbox, SwitchedOffForDebuggingLetsTheReaderThrough) {
    ScratchDir dir;
    ScopedEnv off("FLOWSURF_READER_SANDBOX", "off");
    const std::string what = refusal(dir, "socket");
    EXPECT_NE(what.find("socket was not stopped: socket opened"), std::string::npos) << what;
}
