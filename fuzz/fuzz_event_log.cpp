// Viewer event logs (--replay): events or a typed error; what parses formats again.
#include "core/errors.h"
#include "view_events.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        auto events = flowsurf::app::view::parseEventLog(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
        (void)flowsurf::app::view::formatEventLog(events);
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
