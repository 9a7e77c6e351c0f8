#include "skeleton/tangent_field.h"

#include "skeleton/parallel.h"

#include <cmath>
#include <limits>
#include <unordered_set>

namespace flowsurf::skeleton {

namespace {

// A vector of another tangent plane turned into the plane of normal n, its length kept.
glm::vec3 turnInto(const glm::vec3& t, const glm::vec3& n) {
    const glm::vec3 p = t - glm::dot(t, n) * n;
    const float lp = glm::length(p), lt = glm::length(t);
    return lp > 1e-30f ? p * (lt / lp) : glm::vec3(0.0f);
}

// The frame change R from vertex frame `to` into frame (e1, e2): x_e = R x_to.
glm::mat2 frameChange(const glm::vec3& e1, const glm::vec3& e2, const glm::vec3& u, const glm::vec3& v) {
    // glm: m[column][row]; row k is e_k, column m is the target frame's axis m.
    glm::mat2 r;
    r[0][0] = glm::dot(e1, u);
    r[0][1] = glm::dot(e2, u);
    r[1][0] = glm::dot(e1, v);
    r[1][1] = glm::dot(e2, v);
    return r;
}

}  // namespace

std::vector<glm::vec3> tangentialPart(const SurfaceGraph& graph, std::vector<glm::vec3> field) {
    for (size_t v = 0; v < field.size(); ++v) {
        const glm::vec3& n = graph.normals[v];
        field[v] -= glm::dot(field[v], n) * n;
    }
    return field;
}

std::vector<glm::vec3> smoothField(const SurfaceGraph& graph, std::vector<glm::vec3> field, int passes) {
    std::vector<glm::vec3> next(field.size());
    for (int pass = 0; pass < passes; ++pass) {
        detail::parallelFor(field.size(), [&](size_t v) {
            const glm::vec3& n = graph.normals[v];
            glm::vec3 sum = field[v];
            const uint32_t b = graph.neighbourStart[v], e = graph.neighbourStart[v + 1];
            if (!graph.onBoundary[v]) {
                for (uint32_t k = b; k < e; ++k) sum += turnInto(field[graph.neighbours[k]], n);
                next[v] = sum / float(1 + e - b);
                return;
            }
            // On the boundary only along it, where it runs straight on (an interior average
            // would lean inwards; a corner stays as it is): a linear field stays linear.
            uint32_t along[2], count = 0;
            for (uint32_t k = b; k < e; ++k)
                if (graph.boundaryNeighbour[k] && count < 2) along[count++] = graph.neighbours[k];
            const glm::vec3 p = graph.positions[v];
            if (count == 2 && glm::dot(glm::normalize(graph.positions[along[0]] - p),
                                       glm::normalize(graph.positions[along[1]] - p)) < -0.95f)
                next[v] = (sum + turnInto(field[along[0]], n) + turnInto(field[along[1]], n)) / 3.0f;
            else
                next[v] = field[v];
        });
        field.swap(next);
    }
    return field;
}

glm::vec2 toFrame(const SurfaceGraph& graph, uint32_t v, const glm::vec3& t) {
    glm::vec3 u, w;
    tangentFrame(graph.normals[v], u, w);
    return {glm::dot(t, u), glm::dot(t, w)};
}

glm::vec3 fromFrame(const SurfaceGraph& graph, uint32_t v, const glm::vec2& c) {
    glm::vec3 u, w;
    tangentFrame(graph.normals[v], u, w);
    return c.x * u + c.y * w;
}

std::vector<glm::mat2> vertexJacobians(const SurfaceGraph& graph, const std::vector<glm::vec3>& field) {
    const size_t nv = graph.vertexCount();
    std::vector<glm::mat2> sum(nv, glm::mat2(0.0f));
    for (const glm::uvec3& t : graph.triangles) {
        const glm::vec3 p0 = graph.positions[t.x], p1 = graph.positions[t.y], p2 = graph.positions[t.z];
        glm::vec3 nt = glm::cross(p1 - p0, p2 - p0);
        const float twiceArea = glm::length(nt);
        if (!(twiceArea > 0.0f)) continue;
        nt /= twiceArea;
        // The triangle's frame, its normal on the side of the vertex normals.
        const bool flip = glm::dot(nt, graph.normals[t.x] + graph.normals[t.y] + graph.normals[t.z]) < 0.0f;
        if (flip) nt = -nt;
        const glm::vec3 e1 = glm::normalize(p1 - p0), e2 = glm::cross(nt, e1);
        const glm::vec2 q[3] = {{0, 0}, {glm::dot(p1 - p0, e1), glm::dot(p1 - p0, e2)},
                                {glm::dot(p2 - p0, e1), glm::dot(p2 - p0, e2)}};
        const float signedTwice = q[1].x * q[2].y - q[1].y * q[2].x;  // +-twiceArea
        glm::mat2 j(0.0f);
        for (int i = 0; i < 3; ++i) {
            const glm::vec2 edge = q[(i + 2) % 3] - q[(i + 1) % 3];
            const glm::vec2 grad = glm::vec2(-edge.y, edge.x) / signedTwice;  // grad of barycentric i
            const glm::vec3& f = field[t[i]];
            const glm::vec2 vi(glm::dot(f, e1), glm::dot(f, e2));
            j[0] += vi * grad.x;  // column 0: d/dx
            j[1] += vi * grad.y;  // column 1: d/dy
        }
        const float area = 0.5f * twiceArea;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = t[k];
            glm::vec3 fu, fv;  // the vertex frame, made again rather than stored (24 bytes a vertex)
            tangentFrame(graph.normals[v], fu, fv);
            const glm::mat2 r = frameChange(e1, e2, fu, fv);
            sum[v] += area * (glm::transpose(r) * j * r);
        }
    }
    // the weights' sum: the adjacent triangles' area, three times the vertex's share
    for (size_t v = 0; v < nv; ++v)
        if (graph.vertexArea[v] > 0.0f) sum[v] /= 3.0f * graph.vertexArea[v];
    return sum;
}

glm::mat2 meanJacobian(const SurfaceGraph& graph, const std::vector<glm::mat2>& jacobians, uint32_t start,
                       const glm::vec3& centre, float radius) {
    glm::vec3 su, sv;
    tangentFrame(graph.normals[start], su, sv);
    std::vector<uint32_t> queue{start};
    std::unordered_set<uint32_t> seen{start};
    glm::mat2 sum(0.0f);
    float weight = 0.0f;
    for (size_t head = 0; head < queue.size(); ++head) {
        const uint32_t v = queue[head];
        glm::vec3 u, w;
        tangentFrame(graph.normals[v], u, w);
        // x_v = R x_start, J_start = R^T J_v R
        const glm::mat2 r = frameChange(u, w, su, sv);
        const float a = std::max(graph.vertexArea[v], 1e-30f);
        sum += a * (glm::transpose(r) * jacobians[v] * r);
        weight += a;
        for (uint32_t k = graph.neighbourStart[v]; k < graph.neighbourStart[v + 1]; ++k) {
            const uint32_t nb = graph.neighbours[k];
            if (glm::length(graph.positions[nb] - centre) > radius) continue;
            if (!seen.insert(nb).second) continue;
            queue.push_back(nb);
        }
        if (seen.size() > 4096) break;  // a radius far above the mesh scale: enough to average
    }
    return weight > 0.0f ? sum / weight : glm::mat2(0.0f);
}

namespace {

std::vector<float> perInputVertex(const SurfaceGraph& graph, const std::vector<float>& welded) {
    std::vector<float> out(graph.inputVertexCount());
    for (size_t i = 0; i < out.size(); ++i) out[i] = welded[graph.weldedVertex(i)];
    return out;
}

}  // namespace

std::vector<float> divergence(const SurfaceGraph& graph, const std::vector<glm::vec3>& fieldWelded) {
    const std::vector<glm::mat2> j = vertexJacobians(graph, tangentialPart(graph, fieldWelded));
    std::vector<float> d(j.size());
    for (size_t v = 0; v < j.size(); ++v) d[v] = j[v][0][0] + j[v][1][1];
    return perInputVertex(graph, d);
}

std::vector<float> normalizedDivergence(const SurfaceGraph& graph, const std::vector<glm::vec3>& fieldWelded) {
    std::vector<glm::vec3> unit = tangentialPart(graph, fieldWelded);
    std::vector<uint8_t> zero(unit.size(), 0);
    for (size_t v = 0; v < unit.size(); ++v) {
        const float len = glm::length(unit[v]);
        if (len > 0.0f) unit[v] /= len; else zero[v] = 1;
    }
    const std::vector<glm::mat2> j = vertexJacobians(graph, unit);
    std::vector<float> d(j.size());
    for (size_t v = 0; v < j.size(); ++v)
        d[v] = zero[v] ? std::numeric_limits<float>::quiet_NaN() : j[v][0][0] + j[v][1][1];
    return perInputVertex(graph, d);
}

}  // namespace flowsurf::skeleton
