// flowsurf-reader: the process every file is read in (see reader_process.h). Started by
// the library with the socket on fd 3 and the reasons pipe on fd 4; limits itself and
// enters its sandbox (sandbox.h), then answers requests (each: its CPU-time and memory
// budgets, the op, its arguments) until Quit or end of stream. A crash, abort or limit hit
// here ends this process only; the library reports it as a FormatError.
#include "core/errors.h"
#include "io/reader/file_inspect.h"
#include "io/reader/reader_wire.h"
#include "io/reader/sandbox.h"
#include "io/reader/surface_pipeline.h"
#include "io/reader/vtk_messages.h"
#include "io/reader/vtk_sources.h"

#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <new>

using namespace flowsurf;
namespace w = flowsurf::io::wire;
namespace sandbox = flowsurf::io::sandbox;

namespace {

// The open multi-step source of Open/Step requests.
struct OpenSource {
    std::string path;
    io::detail::VtkMessageTrap trap;
    std::unique_ptr<io::detail::StepSource> source;
};

// Answers one request into `out` (status Ok and the payload). Throws what the reader throws.
bool answer(w::Op op, w::Reader& in, w::Writer& out, std::unique_ptr<OpenSource>& open) {
    switch (op) {
        case w::Op::Open: {
            std::string path = in.str();
            io::SourceOptions options;
            w::record(in, options);
            open.reset();  // one source at a time: the previous one's data goes first
            auto s = std::make_unique<OpenSource>();
            s->path = path;
            s->source = io::detail::openSource(path, s->trap, options);
            out.u8(uint8_t(w::Status::Ok));
            out.str(s->source->format());
            out.field(s->source->times());
            open = std::move(s);
            return true;
        }
        case w::Op::Step: {
            uint64_t i = in.u64();
            if (!open || i >= open->source->stepCount()) throw FormatError("reader: step request out of range");
            core::SurfaceMesh m = io::detail::readSurfaceMesh(open->source->readStep(size_t(i)), open->trap,
                                                              io::detail::stepLabel(open->path, *open->source, i));
            out.u8(uint8_t(w::Status::Ok));
            w::record(out, m);
            return true;
        }
        case w::Op::Inspect: {
            const std::string path = in.str();
            io::SourceOptions options;
            w::record(in, options);
            const io::FileInfo info = io::detail::inspectFileHere(path, options);
            out.u8(uint8_t(w::Status::Ok));
            w::record(out, info);
            return true;
        }
        case w::Op::Quit: return false;
    }
    throw FormatError("reader: unknown request");
}

void error(w::Writer& out, w::Status status, const char* what) {
    out.u8(uint8_t(status));
    out.str(what);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        sandbox::start(sandbox::parseArgs(argc, argv));
    } catch (const std::exception& e) {
        const std::string why = std::string("could not enter its sandbox: ") + e.what();
        [[maybe_unused]] ssize_t n = ::write(sandbox::kReasonFd, why.data(), why.size());
        return 70;
    }
    std::unique_ptr<OpenSource> open;
    w::Writer out(sandbox::kSocketFd);
    for (;;) {
        w::Reader in(sandbox::kSocketFd);
        w::Op op;
        try {
            const uint64_t cpuSeconds = in.u64(), memoryMb = in.u64();
            op = w::Op(in.u8());
            sandbox::limitRequest(memoryMb, cpuSeconds);
        } catch (const w::Broken&) {
            return 0;  // the library closed the socket
        }
        try {
            if (!answer(op, in, out, open)) return 0;
        } catch (const w::Broken&) {
            return 0;
        } catch (const IoError& e) {
            error(out, w::Status::IoError, e.what());
        } catch (const FormatError& e) {
            error(out, w::Status::FormatError, e.what());
        } catch (const FieldError& e) {
            error(out, w::Status::FieldError, e.what());
        } catch (const ConfigError& e) {
            error(out, w::Status::ConfigError, e.what());
        } catch (const std::bad_alloc&) {
            const unsigned long long mb = sandbox::memoryLimitMb();
            error(out, w::Status::Other,
                  mb > 0 ? ("the reader needed more than " + std::to_string(mb) +
                            " MiB (its memory limit for this input; FLOWSURF_READER_MEMORY_MB sets another)")
                               .c_str()
                         : "the reader ran out of memory");
        } catch (const std::exception& e) {
            error(out, w::Status::Other, e.what());
        }
        // Every reply ends with the warnings raised while answering.
        const std::vector<std::string> warnings = io::detail::takeWarnings();
        out.u64(warnings.size());
        for (const auto& text : warnings) out.str(text);
        if (!out.flush()) return 0;
    }
}
