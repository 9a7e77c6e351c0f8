// flowsurf — one time step of the surface on the GPU: interleaved position, normal and
// tangential velocity per vertex (§0), and the triangles. Shared by every method.
#pragma once

#include "core/mesh.h"
#include "core/value_range.h"
#include "gl/objects.h"
#include "parallel/piece_seams.h"
#include "parallel/process_group.h"
#include "params/params.h"

#include <span>
#include <string>
#include <vector>

namespace flowsurf::methods {

// The data statistics an upload scales by: speeds (dt, the clamp, the velocity mask) and the
// colour and mask ranges. Made from the mesh itself or, when the mesh is one piece of a
// surface split over processes, from every piece (wholeSurfaceStatistics), so that all
// pieces scale their vectors and colours alike.
struct SurfaceStatistics {
    float speedP98 = 0.0f;       // 98th percentile of the non-zero tangential speeds
    float clampSpeed = 0.0f;     // CommonParams::speedPercentile-th percentile; 0: no clamp
    float maxSpeed = 0.0f;       // largest advection speed after clamping or normalising
    glm::vec2 colorRange{0.0f, 1.0f};
    glm::vec2 colorDataRange{1.0f, 0.0f};  // the colour values' own min .. max (legend end marks)
    glm::vec2 maskRange{0.0f, 1.0f};  // with CommonParams::maskBy
    core::Bounds bounds;
    // Triangles of the whole surface (every piece; 0: not counted): what decisions that
    // change pixels (the surface raster path) are made from, the same on every process.
    size_t triangles = 0;
};
// The per-vertex values the statistics are made of: tangential speed, the colour and mask
// scalars (when CommonParams names them), each vertex's share of the area (the weights of
// the robust ranges), and the bounds.
struct StatisticsSamples {
    std::vector<float> speed, color, mask, area;
    core::Bounds bounds;
};
StatisticsSamples statisticsSamples(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                    const CommonParams& params);
SurfaceStatistics summarize(const StatisticsSamples& samples, const CommonParams& params);

// The colour and mask ranges that CommonParams leave to the data (no MIN:MAX given), made
// over every sample set added: one mesh, the gathered pieces of a parallel render, or each
// step of a series (added a step at a time; memory stays bounded, core::ValueDistribution).
// Throws ConfigError naming the option when a log colour scale meets a range that is not
// positive.
class RangeAccumulator {
public:
    explicit RangeAccumulator(const CommonParams& params) : params_(params) {}
    void add(const StatisticsSamples& samples);
    // The colour range: the given one, else the range of colorRangeMode (auto: the data
    // range of what was added); speed: 0 .. its 98th percentile (robust, auto), min .. max
    // (data), the robust rule in log10 (log scale).
    glm::vec2 colorRange() const;
    glm::vec2 colorDataRange() const { return colorData_; }  // min .. max of the colour values added
    glm::vec2 maskRange() const;  // as colorRange, for --mask-by (linear)
    float speedP98() const { return speedP98_; }

private:
    bool robustColor() const;  // whether the ranges need the distributions
    bool robustMask() const;

    CommonParams params_;
    core::ValueDistribution color_, mask_;  // area-weighted, robust ranges only
    glm::vec2 colorData_{1.0f, 0.0f}, maskData_{1.0f, 0.0f};
    float speedP98_ = 0.0f;
};
// Collective: the statistics of the surface whose piece on this process is `piece`.
SurfaceStatistics wholeSurfaceStatistics(ProcessGroup& group, const core::SurfaceMesh& piece,
                                         const std::string& fieldName, const CommonParams& params);

class SurfaceGpu {
public:
    SurfaceGpu() = default;
    // Uploads `mesh` with the vector field `fieldName` made tangential, scaled for
    // advection as `params` say (speedPercentile, normalize). Throws FieldError.
    // `withEdges`: also build the edge adjacency the IBFVS edge mask draws. `whole`: the
    // statistics to scale by when `mesh` is one piece of a larger surface (null: its own);
    // `seams`: then its seams (piece_seams.h), drawn as interior edges, not as boundaries.
    SurfaceGpu(const core::SurfaceMesh& mesh, const std::string& fieldName, const CommonParams& params = {},
               bool withEdges = false, const SurfaceStatistics* whole = nullptr, const PieceSeams* seams = nullptr);

    // A new time step of the same topology (interpolated positions and vectors): rewrites
    // the vertex buffer in place, keeping triangles and edge adjacency. False (nothing
    // done) if the vertex or triangle count differs: build a new SurfaceGpu then.
    bool updateVertices(const core::SurfaceMesh& mesh, const std::string& fieldName, const CommonParams& params,
                        const SurfaceStatistics* whole = nullptr);

    void draw() const;  // binds the VAO and draws the triangles
    // The same triangles in the same order as `pieces` draws, with a glFlush after each
    // but the last, so that a renderer which bins a draw on the calling thread before its
    // raster threads start (llvmpipe) rasterises one piece while it bins the next.
    void drawInPieces(int pieces) const;
    // Draws every edge as GL_LINES_ADJACENCY (v0, v1, opposite vertex of the triangle
    // on each side; boundary edges repeat the one opposite vertex). Needs withEdges.
    void drawEdgesAdjacency() const;
    bool hasEdges() const { return edgeCount_ + seamCount_ > 0; }
    // The interleaved vertices (surface_vertex in gpu_bindings.h: position, normal,
    // velocity, colour value and mask value, padded to whole RGBA32F texels) and the
    // triangle indices, for passes that pair the geometry with other per-vertex data.
    GLuint vertexBuffer() const { return vertices_.id(); }
    GLuint indexBuffer() const { return indices_.id(); }
    // The same two buffers as buffer textures: vertices as RGBA32F (surface_vertex::kTexels),
    // triangles as RGB32UI (one texel a triangle). Null when either is longer than the
    // renderer's GL_MAX_TEXTURE_BUFFER_SIZE.
    const gl::BufferTexture& vertexTexture() const { return vertexTexture_; }
    const gl::BufferTexture& triangleTexture() const { return triangleTexture_; }
    size_t triangleCount() const { return triangles_; }
    // The whole surface's triangles when this is one piece of it (SurfaceStatistics::
    // triangles), else triangleCount(): what the raster path is chosen by.
    size_t wholeTriangleCount() const { return wholeTriangles_; }
    // Largest speed of the advection velocity (after clamping/normalising): sets dt.
    float maxSpeed() const { return maxSpeed_; }
    // Speed above which vectors were clamped (0: none, or normalised instead).
    float clampSpeed() const { return clampSpeed_; }
    // Top of the colour map's speed range (98th percentile of the true speed).
    float colorSpeedMax() const { return colorSpeedMax_; }
    // The values at the ends of the colour map in this upload, and what they are.
    glm::vec2 colorRange() const { return colorRange_; }
    // The colour values' own min .. max in this upload: beyond colorRange() they are
    // clamped to the map's ends (the legend marks those ends).
    glm::vec2 colorDataRange() const { return colorDataRange_; }
    const std::string& colorName() const { return colorName_; }
    // The field is a line field (principal directions): its sign carries no meaning.
    bool lineField() const { return lineField_; }
    const core::Bounds& bounds() const { return bounds_; }
    // Boxes around this mesh's own vertices (surfaceParts; bounds() is the whole surface's
    // when this is a piece): what projects to the pixels it can cover.
    std::span<const core::Bounds> pieceParts() const { return pieceParts_; }
    // Up to kPositionSamples vertex positions spread over the mesh (every n-th): where the
    // surface is when the bounds say too little (a camera inside them, dtForStep).
    static constexpr size_t kPositionSamples = 4096;
    const std::vector<glm::vec3>& positionSamples() const { return positionSamples_; }
    // Increments with every upload: methods compare it to see the dynamic case.
    uint64_t generation() const { return generation_; }

private:
    // Tangential, clamped/normalised vectors interleaved with position, normal and speed;
    // sets the speed statistics and bounds.
    std::vector<float> interleave(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                  const CommonParams& params, const SurfaceStatistics* whole);

    gl::Buffer vertices_, indices_;
    gl::BufferTexture vertexTexture_, triangleTexture_;
    gl::VertexArray vao_, edgeVao_, seamVao_;
    gl::Buffer edgeIndices_, seamPositions_;
    size_t edgeCount_ = 0, seamCount_ = 0;
    size_t triangles_ = 0;
    size_t wholeTriangles_ = 0;
    float maxSpeed_ = 0.0f;
    float clampSpeed_ = 0.0f;
    float colorSpeedMax_ = 0.0f;
    glm::vec2 colorRange_{0.0f, 1.0f};
    glm::vec2 colorDataRange_{1.0f, 0.0f};
    std::string colorName_;
    bool lineField_ = false;
    core::Bounds bounds_;
    std::vector<core::Bounds> pieceParts_;
    std::vector<glm::vec3> positionSamples_;
    uint64_t generation_ = 0;
};

// Picks the field to show: `requested` if given (FieldError if absent), else the mesh's
// defaultField() (the first that is not zero everywhere).
std::string selectField(const core::SurfaceMesh& mesh, const std::string& requested,
                        const std::string& where);

}  // namespace flowsurf::methods
