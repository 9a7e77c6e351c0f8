// flowsurf view — the interactive viewer: a GLFW window with a Dear ImGui panel over
// the same renderers as `render`, or the same loop headless (EGL, no window) for
// replayed sessions. See view_state.h for what input does and view_events.h for logs.
#pragma once

#include "cli_options.h"

#include <string>

namespace flowsurf::app::view {

struct ViewOptions {
    std::string play;          // --play FILE: replay an event log
    std::string recordEvents;  // --record-events FILE: write the session's events
    std::string stats;         // --stats FILE.json: per-frame times
    std::string compare;       // --compare isa,ibfvs,hybrid: views side by side
    bool headless = false;     // --headless: EGL, no window (needs --play)
    // --size given (command line or config): the views' size; else the window suits the screen.
    bool sizeGiven = false;
};

// Runs the viewer until quit; throws what loading the initial input throws when headless
// (in a window the error is shown instead).
int runView(const RenderOptions& options, const ViewOptions& view);

}  // namespace flowsurf::app::view
