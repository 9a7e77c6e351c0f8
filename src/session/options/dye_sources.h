// flowsurf — the dye options' value syntaxes (no GL): sources on the command line
// (`X,Y,Z[:RADIUS[:COLOR]]`, several joined by ';') and the dye file (JSON list of sources
// with start and stop frames).
#pragma once

#include "methods/common/dye_source.h"

#include <string>
#include <vector>

namespace flowsurf::session {

// "X,Y,Z[:RADIUS[:COLOR]]" separated by ';' (empty: none). Sources without a colour take
// the next of methods::kDyePalette. Throws ConfigError naming `what`.
std::vector<methods::DyeSource> parseDyeSources(const std::string& text, const std::string& what = "--dye");
// The text parseDyeSources reads back exactly (start and stop are not part of it).
std::string dyeSourcesText(const std::vector<methods::DyeSource>& sources);
// A dye file: {"sources": [{"point": [x, y, z], "radius": r, "color": "red" | "#rrggbb" |
// [r, g, b], "start": frame, "stop": frame}, ...]} or the list alone; only "point" is
// required. Throws IoError, FormatError or ConfigError naming the file and the entry.
std::vector<methods::DyeSource> readDyeFile(const std::string& path);

}  // namespace flowsurf::session
