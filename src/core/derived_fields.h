// flowsurf — vector fields derived from a mesh alone, for surfaces without vectors
// (--field NAME): principal curvature directions for shape rendering [L §V-B]
// (curvature-max, curvature-min; Rusinkiewicz 2004), the surface gradient of a point
// scalar (gradient:ARRAY) and the tangential part of a constant direction (down:x,y,z,
// [L] Fig. 15's "dirt running down"). No GL.
#pragma once

#include "core/mesh.h"

#include <array>
#include <string>

namespace flowsurf::core {

struct DerivedFieldOptions {
    float curvatureRadius = 0.0f;  // average curvature tensors over this radius (object units; 0: one ring)
};

// What --field accepts besides the stored arrays (ARRAY and X,Y,Z stand for a value).
inline constexpr std::array<const char*, 4> kDerivedFieldSyntax{"curvature-max", "curvature-min", "gradient:ARRAY",
                                                                "down:X,Y,Z"};
bool isDerivedField(const std::string& name);
// Principal directions have no sign (line fields): methods orient them (see below).
bool isLineField(const std::string& name);

// Adds the field `name` to `mesh`. Throws ConfigError (bad spec) or FieldError (the
// scalar of gradient:ARRAY is absent, naming the scalars there are).
void addDerivedField(SurfaceMesh& mesh, const std::string& name, const DerivedFieldOptions& options = {});

// Per-vertex principal curvatures k1 >= k2 (positive where the normals diverge, as on a
// sphere with outward normals) and their unit directions. Per-face second fundamental
// forms from the normals' change along the edges (least squares), rotated into each
// vertex's frame and averaged with the faces' areas [Rusinkiewicz 2004].
struct Curvature {
    std::vector<float> k1, k2;
    std::vector<glm::vec3> dir1, dir2;
};
Curvature principalCurvatures(const SurfaceMesh& mesh, float radius = 0.0f);

// Orients a line field consistently: signs are propagated along a maximum spanning tree
// of the vertex graph weighted by |d_i . d_j|, so the sign flips that remain (where the
// field is not orientable, or around umbilics) lie on the few edges outside the tree
// where neighbours disagree most. Returns the number of edges left with d_i . d_j < 0.
size_t orientLineField(std::vector<glm::vec3>& dirs, const std::vector<glm::uvec3>& triangles);

}  // namespace flowsurf::core
