// flowsurf — analytic scenes for the demo, the tests and the benchmarks:
// `builtin:NAME` or `builtin:NAME:TRIANGLES` (approximate triangle count).
#pragma once

#include "core/mesh.h"

#include <string>
#include <vector>

namespace flowsurf::core {

struct BuiltinInfo {
    std::string name;
    std::string description;
};
const std::vector<BuiltinInfo>& builtinScenes();

// True if `spec` starts with "builtin:".
bool isBuiltinSpec(const std::string& spec);

// Makes the scene named by "builtin:NAME[:TRIANGLES]". Every scene has one field named
// "velocity"; the time-dependent one has several time steps. Throws ConfigError.
Dataset makeBuiltin(const std::string& spec);

// Building blocks, also used directly by tests.
SurfaceMesh makeUvSphere(float radius, int slices, int stacks);
SurfaceMesh makeTorus(const glm::vec3& center, float majorR, float minorR, int nu, int nv);
// A w x h rectangle in the plane spanned by axes u, v through `center`, n x m cells.
SurfaceMesh makeRectangle(const glm::vec3& center, const glm::vec3& u, const glm::vec3& v,
                          float w, float h, int n, int m);
// Appends b to a (fields matched by position in the list).
void appendMesh(SurfaceMesh& a, const SurfaceMesh& b);

}  // namespace flowsurf::core
