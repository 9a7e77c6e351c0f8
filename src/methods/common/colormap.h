// flowsurf — perceptual colour maps as 256-entry lookup textures for the overlay.
#pragma once

#include "gl/objects.h"
#include "methods/common/params.h"

#include <array>
#include <glm/glm.hpp>

namespace flowsurf::methods {

// Colour at t in [0,1] (sRGB-encoded, as stored in the PNG).
glm::vec3 colormapAt(Colormap map, float t);
// 256 x 1 RGBA8 texture of the map.
gl::Texture2D makeColormapTexture(Colormap map);

}  // namespace flowsurf::methods
