// flowsurf — the colour legend (scalar bar): the colour map as a vertical bar with ticks,
// tick labels and a title, rasterised on the CPU (FreeType) into an RGBA8 image that the
// overlay composites into every output (PNG, MP4, compare sheets, the viewer).
#pragma once

#include "params/params.h"
#include "present/text.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace flowsurf::methods {

// Ticks at 1, 2 or 5 x 10^k steps inside [lo, hi], about `count` of them.
std::vector<double> niceTicks(double lo, double hi, int count = 5);
// Ticks for a log scale on [lo, hi] (0 < lo < hi): the decades (every n-th when there are
// many), else 1, 2, 5 x 10^k, else niceTicks.
std::vector<double> logTicks(double lo, double hi, int count = 5);

// What the bar shows [docs/cfd.md, colour ranges]: the values at its ends, the scale, and whether the data
// lies beyond an end, where its values are clamped to the end's colour: an end triangle
// in that colour then caps the bar, as CFD tools mark out-of-range colours.
struct LegendScale {
    glm::vec2 range{0.0f, 1.0f};  // bottom .. top of the bar
    bool log = false;
    bool below = false, above = false;
};
// The scale for colour range `range` of values spanning `dataRange` (lo > hi: unknown).
LegendScale legendScale(const CommonParams& params, glm::vec2 range, glm::vec2 dataRange);
// Where value v sits on the bar, 0 (bottom) .. 1 (top).
double legendPosition(const LegendScale& scale, double v);

// Its two shapes: the bar upright at a side, or lying along the top or bottom (where a wide
// surface leaves room above or below it and none beside it).
enum class LegendLayout { Vertical, Horizontal };

// The legend of an image `imageHeight` pixels high; text is white or black, whichever reads
// on `params.background`. Alpha 0 outside the bar, end triangles, ticks and text. Room for
// the end triangles is kept whether they are drawn or not (the box does not jump).
RgbImage makeLegendImage(const CommonParams& params, const LegendScale& scale, const std::string& title,
                         int imageHeight, LegendLayout layout = LegendLayout::Vertical);
// The same for values `range` with params' scale and no end marks.
RgbImage makeLegendImage(const CommonParams& params, glm::vec2 range, const std::string& title, int imageHeight);

// Where the legend sits in an image of `width` x `height` (bottom-left corner in GL
// pixel coordinates): at the right edge, centred vertically.
glm::ivec2 legendOrigin(const RgbImage& legend, int width, int height);

// A place for a legend of `size` pixels that covers no surface pixel [docs/cfd.md, colour ranges]:
// `depth` is the image's window depth (rows bottom to top, 1 = background). `keep` first
// (a legend stays put while it is free), then the free place nearest the middle of the
// side with the larger free margin (right or left for a vertical legend, top or bottom for a
// horizontal one), on a 4-pixel grid. Null when no place is free.
std::optional<glm::ivec2> freeLegendOrigin(const std::vector<float>& depth, int width, int height, glm::ivec2 size,
                                           std::optional<glm::ivec2> keep = std::nullopt,
                                           LegendLayout layout = LegendLayout::Vertical);

}  // namespace flowsurf::methods
