// flowsurf — the geometry of a tiled parallel render (screen_tiles.h): pixel rectangles,
// the weighted split of the screen into one tile per process, the reweighting by measured
// costs, and the pixels a piece can cover. No GL, no messages: the same inputs give the
// same rectangles on every process.
#pragma once

#include "core/mesh.h"
#include "parallel/pixel_rect.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace flowsurf::methods {

// The pixels `bounds` can cover in a view (`viewProj`, `width` x `height`): its corners'
// projection, a pixel wider on each side, within the image; the whole image when a corner
// lies behind the eye; empty for empty bounds. What a process's piece can draw.
PixelRect projectedRect(const core::Bounds& bounds, const glm::mat4& viewProj, int width, int height);

// Boxes that together hold every vertex of `mesh`: its vertices grouped by the cell of a
// cells^3 grid over its bounds, one box around each group. The rectangle around their
// projections (below) then holds every triangle's pixels (a triangle is the convex hull of
// its vertices), and hugs a curved surface's outline where its own box's projection does
// not (a sphere's over 12 views: 0.56 of its box's rectangle at 8^3 cells, half a sphere
// 0.63). One pass over the vertices: 55 ms for a 10M-triangle sphere.
std::vector<core::Bounds> surfaceParts(const core::SurfaceMesh& mesh, int cells = 8);

// The union of projectedRect over `parts`: the pixels the triangles they hold can cover.
PixelRect projectedRect(std::span<const core::Bounds> parts, const glm::mat4& viewProj, int width, int height);

// `parts` rectangles that together cover width x height, of about equal weight, or of
// weights in proportion to `shares` (one per part, in the order of the result) when given:
// the weights of cellsX x cellsY cells of cellPx pixels (row-major, bottom row first), cut
// recursively across the longer side at the cell boundary nearest the weight's share.
// The same weights give the same rectangles on every process. Rectangles can be empty
// when there are more parts than cells.
std::vector<PixelRect> splitScreen(std::span<const float> cellWeights, int cellsX, int cellsY, int cellPx,
                                   int width, int height, int parts, std::span<const float> shares = {});

// Load balance where a process also has work no split moves (drawing its own piece): each
// process's share of the tile work (splitScreen's `shares`) such that its tile's measured
// cost (`tileMs`, per unit of share as measured) plus its own (`ownMs`) is even: the mean
// of the totals less its own, none where its own is over the mean. Equal shares when
// nothing was measured.
std::vector<float> tileShares(std::span<const float> tileMs, std::span<const float> ownMs);

// Load balance from measured costs: the cell weights of the last split (`weights`, cellsX
// per row of cellPx pixels) scaled so that each tile's cells carry its measured cost
// (`ms[t]`, tile t of `tiles`): a cell's new weight is its weight times its tile's cost
// per unit of weight over the mean cost per unit of weight. A split of the result gives the
// tiles that took longer fewer cells.
std::vector<float> costWeights(std::span<const float> weights, int cellsX, int cellPx,
                               const std::vector<PixelRect>& tiles, std::span<const float> ms);

}  // namespace flowsurf::methods
