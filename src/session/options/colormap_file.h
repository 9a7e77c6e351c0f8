// flowsurf — ParaView's JSON colour map files (File > Export of the colour map editor):
// a list of presets, each with "Name" and "RGBPoints" = [x0, r0, g0, b0, x1, ...].
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace flowsurf::session {

// The first preset's colours sampled at 256 evenly spaced x over its range, linear in
// RGB between the points (a "Diverging" or "Lab" ColorSpace is approximated by RGB).
// Throws IoError (unreadable) or ConfigError (not a ParaView colour map), naming the file.
std::vector<glm::vec3> readParaViewColormap(const std::string& path);

}  // namespace flowsurf::session
