// flowsurf-reader: the process every file is read in (see io/reader_process.h). Started by
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
    io::detail::VtkMessageTrap trap;
    std::unique_ptr<io::detail::StepSource> source;
};

// Answers one request into `out` (status Ok and the payload). Throws what the reader throws.
void answer(const w::Request& request, w::Writer& out, std::unique_ptr<OpenSource>& open) {
    switch (request.op) {
        case w::Op::Open: {
            open.reset();  // one source at a time: the previous one's data goes first
            auto s = std::make_unique<OpenSource>();
            s->source = io::detail::openSource(request.path, s->trap, request.options);
            out.field(w::Status::Ok);
            const w::SourceInfo info{s->source->format(), s->source->times()};
            w::record(out, info);
            open = std::move(s);
            return;
        }
        case w::Op::Step: {
            if (!open || request.step >= open->source->stepCount())
                throw FormatError("reader: step request out of range");
            io::detail::StepSource& source = *open->source;
            const size_t i = size_t(request.step);
            const std::string label = w::stepLabel(source.path(), source.times(), i);
            const core::SurfaceMesh m = io::detail::readSurfaceMesh(source.readStep(i), open->trap, label);
            out.field(w::Status::Ok);
            w::record(out, m);
            return;
        }
        case w::Op::Inspect: {
            const io::FileInfo info = io::detail::inspectFileHere(request.path, request.options);
            out.field(w::Status::Ok);
            w::record(out, info);
            return;
        }
        case w::Op::Quit: break;
    }
    throw FormatError("reader: unknown request");
}

// The status a reply carries for what the reader threw.
w::Status statusOf(const std::exception& e) {
    if (dynamic_cast<const IoError*>(&e)) return w::Status::IoError;
    if (dynamic_cast<const FormatError*>(&e)) return w::Status::FormatError;
    if (dynamic_cast<const FieldError*>(&e)) return w::Status::FieldError;
    if (dynamic_cast<const ConfigError*>(&e)) return w::Status::ConfigError;
    return w::Status::Other;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        sandbox::start(argc, argv);
    } catch (const std::exception& e) {
        const std::string why = std::string("could not enter its sandbox: ") + e.what();
        [[maybe_unused]] ssize_t n = ::write(sandbox::kReasonFd, why.data(), why.size());
        return 70;
    }
    std::unique_ptr<OpenSource> open;
    w::Writer out(sandbox::kSocketFd);
    for (;;) {
        w::Reader in(sandbox::kSocketFd);
        w::Request request;
        try {
            w::record(in, request);
        } catch (const w::Broken&) {
            return 0;  // the library closed the socket
        }
        if (request.op == w::Op::Quit) return 0;
        sandbox::limitRequest(request.memoryMb, request.cpuSeconds);
        try {
            answer(request, out, open);
        } catch (const std::bad_alloc&) {
            const unsigned long long mb = sandbox::memoryLimitMb();
            out.field(w::Status::Other);
            out.field(mb > 0 ? "the reader needed more than " + std::to_string(mb) +
                                   " MiB (its memory limit for this input; FLOWSURF_READER_MEMORY_MB sets another)"
                             : std::string("the reader ran out of memory"));
        } catch (const std::exception& e) {
            out.field(statusOf(e));
            out.field(std::string(e.what()));
        }
        // Every reply ends with the warnings raised while answering.
        out.field(io::detail::takeWarnings());
        if (!out.flush()) return 0;
    }
}
