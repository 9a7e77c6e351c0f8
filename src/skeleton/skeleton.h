// flowsurf — the flow topology of a tangential field on a triangle surface, read from the
// field the way an aerodynamicist reads skin-friction lines (doc/topology.md): its critical
// points (Poincaré index and type from the Jacobian in the tangent plane), its separation
// and attachment lines (where skin-friction lines converge or diverge [Kenwright, Henze,
// Levit 1999]) and the surface's Euler characteristic. Analysed once per geometry or time
// step, never per frame. No GL.
// Input: a core::SurfaceMesh and one of its vector fields (any patches or pieces, welded at
// coincident vertices). Output: a Skeleton in the input's coordinates.
// Cost: O(F log F) time, ~100 bytes per vertex.
#pragma once

#include "core/mesh.h"

#include <array>
#include <string>
#include <vector>

namespace flowsurf::skeleton {

enum class PointType { Source, Sink, Saddle, Center, RepellingFocus, AttractingFocus };
inline constexpr std::array<const char*, 6> kPointTypeNames{"source", "sink", "saddle", "center",
                                                             "repelling_focus", "attracting_focus"};
const char* pointTypeName(PointType type);

enum class LineKind { Separation, Attachment };
inline constexpr std::array<const char*, 2> kLineKindNames{"separation", "attachment"};
const char* lineKindName(LineKind kind);

struct SkeletonParams {
    float scale = 0.0f;         // object units: the field is smoothed and its Jacobian fitted over this radius
                                // (0: 3 median edge lengths of the welded surface)
    float cancelSpeed = 0.01f;  // fraction of the 99th-percentile speed, 0..1: zeros joined through a region
                                // slower than this merge into their net index (a node with noise pairs: one node)
    float spiralRatio = 0.1f;   // 0..1: |Im l| / |Re l| below it is a node, |Re l| / |Im l| below it a centre,
                                // a focus between
    bool lines = true;          // also the separation and attachment lines
    float lineStrength = 4.0f;  // lines whose mean strength (below) is under this are dropped, 0..~100
    float lineLength = 0.03f;   // fraction of the bounding-box diagonal: shorter lines are dropped
    float lineAngle = 40.0f;    // degrees, 0..90: a line piece further than this from the flow is not one
    float weldTolerance = 1e-6f;  // fraction of the diagonal: vertices closer than this are one
};

struct CriticalPoint {
    glm::vec3 position{0.0f};  // input coordinates
    PointType type = PointType::Source;
    int index = 1;             // Poincaré index: +1 node / focus / centre, -1 saddle
    glm::vec2 eigenvalues[2];  // (re, im) of the fitted Jacobian's eigenvalues, 1/time
    size_t merged = 1;         // zeros of the field merged into it (1: an isolated zero)
};

struct SkeletonLine {
    LineKind kind = LineKind::Separation;
    std::vector<glm::vec3> points;  // input coordinates, in order along the line
    std::vector<float> strength;    // per point: |rate across - rate along| x diagonal / speed_99
    float length = 0.0f;            // object units
};

struct Skeleton {
    std::vector<CriticalPoint> criticalPoints;
    std::vector<SkeletonLine> lines;
    long eulerCharacteristic = 0;  // of the welded surface, V - E + F
    long indexSum = 0;             // sum of the points' indices
    bool closed = false;           // no boundary edge (then indexSum == eulerCharacteristic)
    size_t parts = 0;              // connected parts of the welded surface
    size_t weldedVertices = 0, triangles = 0;
    size_t zeros = 0;              // zeros of the smoothed field before merging
    float scale = 0.0f;            // the scale used, object units
    float speed99 = 0.0f;          // 99th-percentile speed of the smoothed field
};

// Scalars derived from the field for colour-by and mask-by (doc/topology.md §4): its
// surface divergence and the divergence of the normalised field, the contraction (< 0) and
// expansion (> 0) measure of wall-shear-stress topology [Mazzi et al. 2021].
inline constexpr std::array<const char*, 2> kDerivedScalarNames{"divergence", "normalized-divergence"};
bool isDerivedScalar(const std::string& name);
// Per vertex of `mesh` (welded at coincident vertices as analyze() does); NaN where the
// normalised field is undefined (a zero vector).
std::vector<float> derivedScalar(const core::SurfaceMesh& mesh, const std::vector<glm::vec3>& field,
                                 const std::string& name);

// The skeleton of `field` (per vertex of `mesh`, its tangential part is analysed). Throws
// FieldError (the field is zero everywhere; the surface has no triangle) naming `where`,
// ConfigError for a parameter out of range.
Skeleton analyze(const core::SurfaceMesh& mesh, const std::vector<glm::vec3>& field, const SkeletonParams& params,
                 const std::string& where);

}  // namespace flowsurf::skeleton
