// Shared by the unit tests of the command line: the render options that a list of
// arguments (without the program name) sets, parsed as `flowsurf render` parses them.
#pragma once

#include "cli_options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace flowsurf::testing_cli {

inline session::RenderOptions parseRenderArgs(std::vector<std::string> args) {
    CLI::App app;
    session::RenderOptions o;
    app::addRenderOptions(app, o);
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
    return o;
}

}  // namespace flowsurf::testing_cli
