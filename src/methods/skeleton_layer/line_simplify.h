// flowsurf — the topology lines simplified for one view (SkeletonLayer, each time the camera
// moves): each polyline projected with the frame's camera, Douglas-Peucker in screen space
// (a vertex goes where the line moves by less than a fraction of a pixel and its depth by
// much less than the layer's 1 % depth test), pieces behind the eye or wholly outside the
// view left out. Object-space polylines -> the pieces to draw, each with its kept
// neighbours (the mitred joins). No GL: the same camera gives the same pieces.
#pragma once

#include "core/camera.h"
#include "skeleton/skeleton.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace flowsurf::methods {

struct SimplifyParams {
    float tolerancePx = 0.5f;       // px: the most a dropped vertex lies off its piece on screen (0.25: 1.4x the pieces)
    float depthTolerance = 0.002f;  // of the eye distance: the most it lies off in depth (test: 1 %)
    float reachPx = 8.0f;           // px a drawn piece reaches beyond its ends (width, cap, miter)
};

// A line's vertex in the view: pixels (origin bottom-left), its distance from the eye along
// the view direction (what the depth test compares), and whether it lies in front of the eye
// (clip w > 0, the layer's own test; pieces with an end behind are not drawn).
struct ViewVertex {
    glm::dvec2 px{0.0};
    double eye = 0.0;
    bool inFront = false;
};

// The vertices of `pointsObj` in the view of `camera` over `viewport`.
std::vector<ViewVertex> projectLine(std::span<const glm::vec3> pointsObj, const core::Camera& camera,
                                    const core::Viewport& viewport);

// How far vertex `v` lies off the piece a -> b, in units of the tolerances (<= 1: it may
// go): on screen, its distance to the piece over tolerancePx; in depth, its eye distance
// against the piece's at the same place (window depth interpolated along the piece, as the
// fragment shader does: 1/eye affine on screen in perspective, eye itself when orthographic)
// over depthTolerance x its eye distance. The larger of the two.
double deviation(const ViewVertex& v, const ViewVertex& a, const ViewVertex& b, bool orthographic,
                 const SimplifyParams& p);

// The indices of the vertices kept (ascending): both ends of the line, every vertex behind
// the eye and its neighbours, and within each run in front of the eye those Douglas-Peucker
// keeps with deviation() <= 1 for every vertex dropped between two kept ones.
std::vector<uint32_t> keptVertices(std::span<const ViewVertex> v, bool orthographic, const SimplifyParams& p);

// One piece to draw: vertices a -> b of line `line`, and the kept vertices before a and after
// b (prev == a: a is the line's first vertex, a round cap; next == b: b is its last).
struct ViewPiece {
    uint32_t line = 0;
    uint32_t prev = 0, a = 0, b = 0, next = 0;
};

// The pieces between consecutive kept vertices of every line, less those with an end behind
// the eye and those wholly beyond one side of the viewport widened by reachPx. In the order
// of the lines and along each.
std::vector<ViewPiece> viewPieces(std::span<const skeleton::SkeletonLine> lines, const core::Camera& camera,
                                  const core::Viewport& viewport, const SimplifyParams& p);

}  // namespace flowsurf::methods
