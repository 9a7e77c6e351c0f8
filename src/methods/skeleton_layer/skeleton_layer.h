// flowsurf — the flow topology drawn over a method's image (docs/topology.md §5): critical
// points as glyphs whose shape and colour give the type, separation and attachment lines
// in two colours, a constant width in pixels, anti-aliased (coverage from the distance to
// the line in pixels, a dark outline around the core), hidden where the surface covers them
// (the method's own surface depth). Drawn onto the composite (RGBA8) after the method's
// stages, so the texture under them is the method's; the same result for every method.
// Cost: each time the camera moves, the lines simplified on the CPU for that view
// (line_simplify.h: a few thousand vertices, well under a millisecond) and the kept pieces
// uploaded; then one draw of those pieces (outline and core in one pass, each pixel of a line
// once; on llvmpipe the cost goes with the number of pieces) and one of the points, six
// vertices a quad.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/skeleton_layer/line_simplify.h"
#include "skeleton/skeleton.h"

#include <array>
#include <optional>
#include <vector>

namespace flowsurf::methods {

// How each point type and line kind looks, in one table (the shaders and the legend read it).
struct GlyphStyle {
    glm::vec3 colour;
    int shape;  // 0 disc, 1 square, 2 cross, 3 ring, 4 triangle up, 5 triangle down
};
inline constexpr std::array<GlyphStyle, skeleton::kPointTypeNames.size()> kPointStyles{{
    {{1.00f, 0.85f, 0.10f}, 0},  // source: yellow disc
    {{0.20f, 0.80f, 0.30f}, 1},  // sink: green square
    {{0.97f, 0.97f, 0.97f}, 2},  // saddle: white cross
    {{0.30f, 0.90f, 0.95f}, 3},  // center: cyan ring
    {{1.00f, 0.50f, 0.10f}, 4},  // repelling focus: orange triangle up
    {{0.72f, 0.45f, 1.00f}, 5},  // attracting focus: violet triangle down
}};
inline constexpr std::array<glm::vec3, skeleton::kLineKindNames.size()> kLineColours{{
    {0.95f, 0.12f, 0.12f},  // separation: red
    {0.15f, 0.50f, 1.00f},  // attachment: blue
}};

struct SkeletonStyle {
    bool points = true, lines = true;
    float glyphSize = 11.0f;  // px
    float lineWidth = 2.5f;   // px
};

class SkeletonLayer {
public:
    SkeletonLayer();  // needs a current GL context
    // The result to draw (uploaded once; drawn every frame after).
    void upload(const skeleton::Skeleton& s);
    // Draws onto `composite` (RGBA8, the method's image), hidden by `surfaceDepth`.
    void draw(const gl::Texture2D& composite, const gl::Texture2D& surfaceDepth, const core::Camera& camera,
              const SkeletonStyle& style);
    // Line pieces: of the uploaded lines, and drawn by the last draw() (simplified for its view).
    size_t piecesUploaded() const { return piecesUploaded_; }
    size_t piecesDrawn() const { return size_t(segmentCount_); }

private:
    // The pieces of `lines` simplified for this view, uploaded unless the view is the last one's.
    void simplifyFor(const core::Camera& camera, const core::Viewport& viewport, float reachPx);

    gl::Program lines_, points_;
    gl::VertexArray vao_;
    gl::Framebuffer fbo_;
    gl::Buffer segments_, pointBuffer_;
    gl::Buffer quadCorners_;  // element indices: six per line piece over its four corners
    GLsizei segmentCount_ = 0, pointCount_ = 0;
    std::vector<skeleton::SkeletonLine> polylines_;  // as uploaded, object space
    size_t piecesUploaded_ = 0;
    // the view segments_ holds the pieces of (none after upload)
    std::optional<core::Camera> piecesCamera_;
    core::Viewport piecesViewport_;
    float piecesReachPx_ = 0.0f;
};

}  // namespace flowsurf::methods
