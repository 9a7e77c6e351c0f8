// The reader process's request path: each input, written as a file of the format its
// first byte picks (an EnSight geometry file with its case file, legacy .vtk, .vtp, .vtu,
// Exodus II, STL, PLY, OBJ, .pvd, CGNS), is read through one ReaderProcess, in the sandboxed
// child (fuzz_reader_child: flowsurf-reader built with ASan + UBSan). Whatever the child
// does (an error, a crash, a loop or allocation stopped by its limits), the caller gets a
// surface or a flowsurf::Error naming the file, never a sandbox refusal (reading needs
// no forbidden system call) and never the library's wall-clock deadline (the child's CPU
// limit stops a spinning reader first; scripts/fuzz.sh gives libFuzzer's -timeout room
// for a loaded machine).
// Crashes inside the child are contained by design, so memory errors in our own parsers
// are the business of fuzz_ply and fuzz_obj.
#include "core/errors.h"
#include "io/reader_process.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

const char* const kExtensions[] = {".geo", ".vtk", ".vtp", ".vtu", ".e", ".stl", ".ply", ".obj", ".pvd", ".cgns"};

void writeFile(const std::string& path, const uint8_t* data, size_t size) {
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
}

// The file to read: the input in a folder of its own (the child may read below it); an
// EnSight geometry file is read through a case file naming it.
std::string inputFile(const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        std::string d = "/dev/shm/flowsurf-fuzz-reader-" + std::to_string(getpid());
        mkdir(d.c_str(), 0700);
        const std::string caseFile = d + "/input.case";
        if (FILE* f = std::fopen(caseFile.c_str(), "w")) {
            std::fputs("FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: input.geo\n", f);
            std::fclose(f);
        }
        return d;
    }();
    const std::string ext = kExtensions[data[0] % (sizeof kExtensions / sizeof *kExtensions)];
    writeFile(dir + "/input" + ext, data + 1, size - 1);
    return dir + (ext == ".geo" ? "/input.case" : "/input" + ext);
}

}  // namespace

// The child's AddressSanitizer (read at its start): a runaway allocation fails as
// std::bad_alloc, as RLIMIT_AS makes it fail outside sanitizer builds.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    setenv("ASAN_OPTIONS", "detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=2048", 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static auto* reader = new flowsurf::io::detail::ReaderProcess();  // one child, restarted when it dies
    if (size < 1) return 0;
    const std::string path = inputFile(data, size);
    try {
        reader->readDataset(path, 1);
    } catch (const flowsurf::Error& e) {
        const std::string what = e.what();
        // A reader stopped by its sandbox did something no reading needs (or the
        // allow-list misses a call VTK makes); one stopped by the library's wall-clock
        // deadline escaped its CPU limit: all worth a look. Matched where the library puts
        // them, right after the label (the path, and a series' step): a message may quote
        // the file's own words further on.
        std::string verdict = what.rfind(path, 0) == 0 ? what.substr(path.size()) : "";
        if (verdict.rfind(" (time step ", 0) == 0) verdict.erase(0, verdict.find("): ") + 1);
        const bool stopped = verdict.rfind(": the reader was stopped by its sandbox", 0) == 0 ||
                             verdict.rfind(": the reader took longer than", 0) == 0;
        if (what.find(path) == std::string::npos || stopped) {
            std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
            std::abort();
        }
    }
    return 0;
}
