// flowsurf — the tangential field's derivatives on a welded surface (doc/topology.md §1):
// the field smoothed over a neighbourhood (the analysis scale), its Jacobian in each
// vertex's tangent plane (the area-weighted mean of the piecewise-linear field's constant
// gradient on the adjacent triangles), and from it the surface divergence and the
// divergence of the normalised field [Mazzi et al. 2021]. No GL.
// Cost: O(F) per smoothing pass and for the Jacobians; memory: the field twice while it is
// smoothed, then 20 bytes per vertex for the Jacobians.
#pragma once

#include "skeleton/surface_graph.h"

#include <glm/glm.hpp>

#include <vector>

namespace flowsurf::skeleton {

// Each vertex's vector projected into its tangent plane.
std::vector<glm::vec3> tangentialPart(const SurfaceGraph& graph, std::vector<glm::vec3> field);

// `passes` umbrella-averaging passes: each vertex takes the mean of itself and its
// neighbours, their vectors turned into its tangent plane with their length kept. k passes
// smooth over about sqrt(k) edge lengths.
std::vector<glm::vec3> smoothField(const SurfaceGraph& graph, std::vector<glm::vec3> field, int passes);

// The Jacobian dv/dx of the tangential field at each vertex, in that vertex's
// tangentFrame (glm's column-major mat2: J * (x, y) gives the change of (vu, vv)).
std::vector<glm::mat2> vertexJacobians(const SurfaceGraph& graph, const std::vector<glm::vec3>& field);

// (u, v) coordinates of a tangent vector in vertex `v`'s frame, and back.
glm::vec2 toFrame(const SurfaceGraph& graph, uint32_t v, const glm::vec3& t);
glm::vec3 fromFrame(const SurfaceGraph& graph, uint32_t v, const glm::vec2& c);

// The area-weighted mean Jacobian over the vertices within `radius` of `centre` reached from
// vertex `start` through vertices within the radius, in `start`'s frame.
glm::mat2 meanJacobian(const SurfaceGraph& graph, const std::vector<glm::mat2>& jacobians, uint32_t start,
                       const glm::vec3& centre, float radius);

// Per input vertex (through graph.weldOf): the surface divergence of `field`, and that of
// field / |field| (NaN where the field is zero).
std::vector<float> divergence(const SurfaceGraph& graph, const std::vector<glm::vec3>& fieldWelded);
std::vector<float> normalizedDivergence(const SurfaceGraph& graph, const std::vector<glm::vec3>& fieldWelded);

}  // namespace flowsurf::skeleton
