// flowsurf — the data model: a triangle surface with per-vertex vector fields over
// a list of time steps ([W]/[L] §0 of doc/algorithms.md). No GL here.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace flowsurf::core {

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};
    bool valid() const { return lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z; }
    glm::vec3 center() const { return 0.5f * (lo + hi); }
    float radius() const { return 0.5f * glm::length(hi - lo); }
    void extend(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void extend(const Bounds& b) { if (b.valid()) { extend(b.lo); extend(b.hi); } }
};

// One named per-vertex array with 3 components (velocity, wall shear stress...).
struct VectorField {
    std::string name;
    std::vector<glm::vec3> values;  // one per vertex, object (P-) space units
};

// One named per-vertex scalar (pressure, a converted cell array...). NaN marks "no value
// here" (a field missing on some patches): shown in the NaN colour, never advected.
struct ScalarField {
    std::string name;
    std::vector<float> values;  // one per vertex
};

// The surface at one time step. Positions and triangles may differ between steps
// (dynamic meshes, changing topology [L Fig. 11]).
struct SurfaceMesh {
    std::vector<glm::vec3> positions;   // object space
    std::vector<glm::vec3> normals;     // unit, one per vertex
    std::vector<glm::uvec3> triangles;  // indices into positions
    std::vector<VectorField> fields;    // per-vertex vectors, same count as positions
    std::vector<ScalarField> scalars;   // per-vertex scalars, same count as positions
    // Units of the fields and scalars, by name, where the file gives them (OpenFOAM's
    // dimensions: U -> "m/s", p -> "m2/s2"); an array without an entry has none known.
    std::map<std::string, std::string> units;

    size_t vertexCount() const { return positions.size(); }
    size_t triangleCount() const { return triangles.size(); }
    const VectorField* findField(const std::string& name) const;
    // The field to show when none is named: the first that is not zero everywhere (a CFD
    // wall result's velocity U is zero on the wall; its wall shear stress is not), else the
    // first; null without fields.
    const VectorField* defaultField() const;
    const ScalarField* findScalar(const std::string& name) const;
    Bounds bounds() const;
};

// The triangles of `mesh` whose centroid `keep` accepts, with their vertices and every
// per-vertex array; a vertex shared with rejected triangles appears in both pieces, as on
// the seams of a partitioned dataset (the pieces ParaView's ranks hold).
SurfaceMesh pieceOf(const SurfaceMesh& mesh, const std::function<bool(glm::vec3)>& keep);

struct TimeStep {
    double time = 0.0;
    SurfaceMesh mesh;
};

// What a reader returns: one or more time steps of a surface.
struct Dataset {
    std::string source;              // file name or builtin:NAME, for messages
    std::vector<TimeStep> steps;     // sorted by time, at least one
    Bounds bounds() const;           // over all steps
};

// A scalar to colour or mask by: "ARRAY" (a scalar, or a vector's magnitude) or
// "ARRAY:x|y|z|mag" (one component of a vector, or its magnitude).
struct ScalarSpec {
    std::string array;
    int component = -1;  // 0..2, or -1: the scalar itself / the vector's magnitude
    static ScalarSpec parse(const std::string& text);  // throws ConfigError
    std::string text() const;
};
// Per-vertex values of `spec` on `mesh`; false (out untouched) when the array is absent.
bool evalScalar(const SurfaceMesh& mesh, const ScalarSpec& spec, std::vector<float>& out);
// Finite minimum and maximum of `values` (lo > hi when none is finite).
std::pair<float, float> finiteRange(const std::vector<float>& values);

// Computes area-weighted vertex normals (used when a file carries none).
std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<glm::uvec3>& triangles);

// §0: v <- v - (v.n) n for every vertex.
void makeTangential(std::vector<glm::vec3>& vectors, const std::vector<glm::vec3>& normals);

// Checks a mesh for what would crash or poison rendering: empty, indices out of
// range, field size mismatch, NaN/Inf positions or vectors. Throws FormatError naming
// `where` (file) and the first offending element. Degenerate (zero-area) triangles are
// removed and counted rather than refused; the count is returned.
size_t validateMesh(SurfaceMesh& mesh, const std::string& where);

}  // namespace flowsurf::core
