// flowsurf — the dye options' value syntaxes (no GL): sources on the command line
// (`X,Y,Z[:RADIUS[:COLOR]]`, several joined by ';') and the dye file (JSON list of sources
// with start and stop frames).
#pragma once

#include "params/dye_source.h"

#include <optional>
#include <string>
#include <vector>

namespace flowsurf::session {

// "X,Y,Z[:RADIUS[:COLOR]]" separated by ';' (empty: none). Sources without a colour take
// the next of methods::kDyePalette. Throws ConfigError naming `what`.
std::vector<methods::DyeSource> parseDyeSources(const std::string& text, const std::string& what = "--dye");
// The source that the option's text X,Y,Z:RADIUS:COLOR says, made from its values: what a
// front end that places dye (flowsurf::Renderer::addDye, the viewer's ctrl+click) appends to
// the "dye" option, equal to what its text reads back as. RADIUS >= 0 (0: a few pixels);
// `color` a name, #rrggbb or r,g,b, or none for the palette's colour of the `index`-th
// source. Throws ConfigError naming `what`.
methods::DyeSource dyeSource(const glm::vec3& point, float radius, const std::optional<std::string>& color,
                             size_t index, const std::string& what);
// The text parseDyeSources reads back exactly (start and stop are not part of it).
std::string dyeSourcesText(const std::vector<methods::DyeSource>& sources);
// A dye file: {"sources": [{"point": [x, y, z], "radius": r, "color": "red" | "#rrggbb" |
// [r, g, b], "start": frame, "stop": frame}, ...]} or the list alone; only "point" is
// required. Throws IoError, FormatError or ConfigError naming the file and the entry.
std::vector<methods::DyeSource> readDyeFile(const std::string& path);

}  // namespace flowsurf::session
