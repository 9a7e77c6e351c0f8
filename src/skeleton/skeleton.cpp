#include "skeleton/skeleton.h"

#include "core/errors.h"
#include "skeleton/critical_points.h"
#include "skeleton/separation_lines.h"
#include "skeleton/tangent_field.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::skeleton {

const char* pointTypeName(PointType type) { return kPointTypeNames[size_t(type)]; }
const char* lineKindName(LineKind kind) { return kLineKindNames[size_t(kind)]; }

namespace {

void checkParams(const SkeletonParams& p) {
    auto check = [](bool ok, const char* name, float value, const char* range) {
        if (!ok) throw ConfigError(std::string("topology: ") + name + " " + std::to_string(value) + " is outside " + range);
    };
    check(p.scale >= 0.0f && std::isfinite(p.scale), "scale", p.scale, "[0, inf)");
    check(p.cancelSpeed >= 0.0f && p.cancelSpeed <= 1.0f, "cancel speed", p.cancelSpeed, "[0, 1]");
    check(p.spiralRatio >= 0.0f && p.spiralRatio <= 1.0f, "spiral ratio", p.spiralRatio, "[0, 1]");
    check(p.lineStrength >= 0.0f && std::isfinite(p.lineStrength), "line strength", p.lineStrength, "[0, inf)");
    check(p.lineLength >= 0.0f && p.lineLength <= 1.0f, "line length", p.lineLength, "[0, 1]");
    check(p.lineAngle >= 0.0f && p.lineAngle <= 90.0f, "line angle", p.lineAngle, "[0, 90]");
    check(p.weldTolerance >= 0.0f && p.weldTolerance <= 0.01f, "weld tolerance", p.weldTolerance, "[0, 0.01]");
}

float percentile99(const std::vector<glm::vec3>& f) {
    std::vector<float> speed(f.size());
    for (size_t i = 0; i < f.size(); ++i) speed[i] = glm::length(f[i]);
    if (speed.empty()) return 0.0f;
    auto at = speed.begin() + long(std::min(speed.size() - 1, size_t(0.99 * double(speed.size()))));
    std::nth_element(speed.begin(), at, speed.end());
    return *at;
}

}  // namespace

bool isDerivedScalar(const std::string& name) {
    return std::find(kDerivedScalarNames.begin(), kDerivedScalarNames.end(), name) != kDerivedScalarNames.end();
}

std::vector<float> derivedScalar(const core::SurfaceMesh& mesh, const std::vector<glm::vec3>& field,
                                 const std::string& name) {
    FLOWSURF_CHECK(isDerivedScalar(name) && field.size() == mesh.vertexCount());
    const SurfaceGraph graph = buildSurfaceGraph(mesh);
    const std::vector<glm::vec3> welded = weldValues(graph, field);
    return name == kDerivedScalarNames[0] ? divergence(graph, welded) : normalizedDivergence(graph, welded);
}

Skeleton analyze(const core::SurfaceMesh& mesh, const std::vector<glm::vec3>& field, const SkeletonParams& params,
                 const std::string& where) {
    checkParams(params);
    if (mesh.triangles.empty()) throw FieldError(where + ": the surface has no triangles: no flow topology to find");
    if (field.size() != mesh.vertexCount())
        throw FieldError(where + ": the field has " + std::to_string(field.size()) + " vectors for " +
                         std::to_string(mesh.vertexCount()) + " vertices");

    // (0) the welded surface and the tangential field on it
    const SurfaceGraph graph = buildSurfaceGraph(mesh, params.weldTolerance);
    if (graph.triangles.empty()) throw FieldError(where + ": every triangle is degenerate: no flow topology to find");
    FieldOnGraph on;
    on.scale = params.scale > 0.0f ? params.scale : 3.0f * graph.medianEdge;
    std::vector<glm::vec3> raw = tangentialPart(graph, weldValues(graph, field));
    const float rawSpeed99 = percentile99(raw);
    if (!(rawSpeed99 > 0.0f) && std::all_of(raw.begin(), raw.end(), [](const glm::vec3& v) {
            return v == glm::vec3(0.0f);
        }))
        throw FieldError(where + ": the field's tangential part is zero everywhere: no flow topology to find");

    // (1) smoothed over the scale: k umbrella passes reach about sqrt(k) edges
    const float ratio = graph.medianEdge > 0.0f ? on.scale / graph.medianEdge : 0.0f;
    const int passes = int(std::lround(std::min(double(ratio) * double(ratio), 400.0)));
    on.smoothed = tangentialPart(graph, smoothField(graph, std::move(raw), passes));
    on.speed99 = percentile99(on.smoothed);
    if (!(on.speed99 > 0.0f)) on.speed99 = rawSpeed99;
    on.jacobians = vertexJacobians(graph, on.smoothed);

    // (2) critical points, (3) separation and attachment lines
    Skeleton out;
    out.criticalPoints = findCriticalPoints(graph, on, params, out.zeros);
    if (params.lines) out.lines = findSeparationLines(graph, on, params);
    for (const CriticalPoint& p : out.criticalPoints) out.indexSum += p.index;
    out.eulerCharacteristic = graph.eulerCharacteristic();
    out.closed = graph.closed();
    out.parts = graph.parts;
    out.weldedVertices = graph.usedVertices;
    out.triangles = graph.triangles.size();
    out.scale = on.scale;
    out.speed99 = on.speed99;
    return out;
}

}  // namespace flowsurf::skeleton
