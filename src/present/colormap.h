// flowsurf — colour maps as 256-entry lookup textures for the overlay: perceptual ones
// (viridis, plasma, turbo, cool-warm), gray, jet (asked for), or a table from a file.
#pragma once

#include "gl/objects.h"
#include "params/params.h"

#include <array>
#include <glm/glm.hpp>

namespace flowsurf::methods {

// Colour at t in [0,1] (sRGB-encoded, as stored in the PNG).
glm::vec3 colormapAt(Colormap map, float t);
// The map `params` select: their colormapTable when not empty, else `colormap`.
glm::vec3 colormapAt(const CommonParams& params, float t);
// 256 x 1 RGBA8 texture of that map.
gl::Texture2D makeColormapTexture(const CommonParams& params);

}  // namespace flowsurf::methods
