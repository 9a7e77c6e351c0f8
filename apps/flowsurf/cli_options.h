// flowsurf — the option table (session/options/options.h) as CLI11 options of a subcommand:
// --help shows each option's group, kind, range and default from the table.
#pragma once

#include "session/options/options.h"

#include <CLI/CLI.hpp>

namespace flowsurf::app {

using namespace flowsurf::session;

// Adds the render options, grouped by topic, to `cmd`.
void addRenderOptions(CLI::App& cmd, RenderOptions& opt);

}  // namespace flowsurf::app
