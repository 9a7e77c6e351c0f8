// flowsurf — the colour legend (scalar bar): the colour map as a vertical bar with ticks,
// tick labels and a title, rasterised on the CPU (FreeType) into an RGBA8 image that the
// overlay composites into every output (PNG, MP4, compare sheets, the viewer).
#pragma once

#include "methods/common/params.h"
#include "methods/common/text.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace flowsurf::methods {

// Ticks at 1, 2 or 5 x 10^k steps inside [lo, hi], about `count` of them.
std::vector<double> niceTicks(double lo, double hi, int count = 5);

// The legend for values `range` (bottom .. top of the bar) of an image `imageHeight`
// pixels high; text is white or black, whichever reads on `params.background`. Alpha 0
// outside the bar, ticks and text.
RgbImage makeLegendImage(const CommonParams& params, glm::vec2 range, const std::string& title, int imageHeight);

// Where the legend sits in an image of `width` x `height` (bottom-left corner in GL
// pixel coordinates): at the right edge, centred vertically.
glm::ivec2 legendOrigin(const RgbImage& legend, int width, int height);

}  // namespace flowsurf::methods
