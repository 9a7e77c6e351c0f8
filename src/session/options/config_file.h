// flowsurf — view state as a JSON config file, one key per option of the option table
// (options.h), as the viewer's "Save settings" writes it and `--config FILE` reads it:
//   {"flowsurf-config": 1, "input": "case.vtp", "method": "hybrid", "alpha": 0.08,
//    "eye": [1, 2, 3], "size": "800x600", "edge-mask": false, ...}
// Numbers, strings, booleans and [x, y, z] arrays are accepted for any option whose text
// syntax they spell. Options on the command line override the file.
#pragma once

#include "session/options/options.h"

#include <optional>
#include <string>

namespace flowsurf::session {

// Applies every key of the file to `o`. Throws IoError (cannot open), FormatError (not
// JSON, not an object) or ConfigError (unknown key, bad value), naming the file and key.
void applyConfigFile(const std::string& path, RenderOptions& o);
// The whole saved state of `o` (every option with `saved` and a value) as JSON text.
std::string configJson(const RenderOptions& o);
// The FILE of `--config FILE` or `--config=FILE` in a command line, if any.
std::optional<std::string> findConfigArgument(int argc, const char* const* argv);

}  // namespace flowsurf::session
