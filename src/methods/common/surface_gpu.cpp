#include "methods/common/surface_gpu.h"

#include "core/derived_fields.h"
#include "core/errors.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace flowsurf::methods {

namespace {
std::atomic<uint64_t> nextGeneration{1};
}

std::string selectField(const core::SurfaceMesh& mesh, const std::string& requested, const std::string& where) {
    if (mesh.fields.empty())
        throw FieldError(where + ": no 3-component point array to use as the vector field");
    if (requested.empty()) return mesh.defaultField()->name;
    if (mesh.findField(requested)) return requested;
    std::string names;
    for (const auto& f : mesh.fields) names += (names.empty() ? "" : ", ") + f.name;
    throw FieldError(where + ": no vector field '" + requested + "' (available: " + names + ")");
}

namespace {
// Per edge: (v0, v1, opposite in the triangle with v0->v1, opposite in the other one).
std::vector<uint32_t> edgeAdjacency(const std::vector<glm::uvec3>& triangles) {
    std::unordered_map<uint64_t, size_t> slot;  // undirected edge -> index into out/4
    slot.reserve(triangles.size() * 2);
    std::vector<uint32_t> out;
    out.reserve(triangles.size() * 6);
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) {
            uint32_t a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
            uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            auto [it, fresh] = slot.try_emplace(key, out.size() / 4);
            if (fresh) out.insert(out.end(), {a, b, c, c});  // boundary until a second side shows up
            else out[it->second * 4 + 3] = c;               // manifold: the other side
        }
    return out;
}

// The p-th percentile (0..100) of the non-zero values; 0 if none.
float percentile(std::vector<float> values, float p) {
    values.erase(std::remove(values.begin(), values.end(), 0.0f), values.end());
    if (values.empty()) return 0.0f;
    size_t k = std::min(values.size() - 1, size_t(double(p) / 100.0 * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + long(k), values.end());
    return values[k];
}

// Values of a colour/mask scalar; absent arrays (a step lacking them) give NaN.
std::vector<float> scalarValues(const core::SurfaceMesh& mesh, const std::string& spec) {
    std::vector<float> v;
    if (!core::evalScalar(mesh, core::ScalarSpec::parse(spec), v))
        v.assign(mesh.vertexCount(), std::numeric_limits<float>::quiet_NaN());
    return v;
}

// (v - lo) / (hi - lo), NaN kept; a flat range maps to 0 (as a zero speed did).
void normalizeInPlace(std::vector<float>& v, glm::vec2 range) {
    const float span = range.y - range.x;
    for (float& x : v) x = span > 0.0f ? (x - range.x) / span : (std::isnan(x) ? x : 0.0f);
}

std::vector<float> tangentialSpeed(const core::SurfaceMesh& mesh, const core::VectorField& field,
                                   std::vector<glm::vec3>* velOut = nullptr) {
    std::vector<glm::vec3> vel = field.values;
    core::makeTangential(vel, mesh.normals);
    std::vector<float> speed(vel.size());
    for (size_t i = 0; i < vel.size(); ++i) speed[i] = glm::length(vel[i]);
    if (velOut) *velOut = std::move(vel);
    return speed;
}
}  // namespace

StatisticsSamples statisticsSamples(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                    const CommonParams& params) {
    StatisticsSamples s;
    if (const core::VectorField* field = mesh.findField(fieldName)) s.speed = tangentialSpeed(mesh, *field);
    if (!params.colorBy.empty()) s.color = scalarValues(mesh, params.colorBy);
    if (!params.maskBy.empty()) s.mask = scalarValues(mesh, params.maskBy);
    s.bounds = mesh.bounds();
    return s;
}

SurfaceStatistics summarize(const StatisticsSamples& samples, const CommonParams& params) {
    SurfaceStatistics st;
    st.speedP98 = percentile(samples.speed, 98.0f);
    const bool given = params.colorRange.x <= params.colorRange.y && !params.colorRangeAuto;
    if (given) st.colorRange = params.colorRange;
    else if (params.colorBy.empty()) st.colorRange = {0.0f, st.speedP98};
    else {
        auto [lo, hi] = core::finiteRange(samples.color);
        st.colorRange = {lo, hi};
    }
    if (!params.maskBy.empty()) {
        auto [lo, hi] = core::finiteRange(samples.mask);
        st.maskRange = params.maskRange.x <= params.maskRange.y ? params.maskRange : glm::vec2(lo, hi);
    }
    st.clampSpeed = params.speedPercentile >= 100.0f ? 0.0f : percentile(samples.speed, params.speedPercentile);
    // The largest advection speed after clamping or normalising (what interleave writes).
    float raw = 0.0f;
    for (float v : samples.speed) raw = std::max(raw, v);
    st.maxSpeed = params.normalize ? (raw > 0.0f ? 1.0f : 0.0f)
                  : st.clampSpeed > 0.0f ? std::min(raw, st.clampSpeed)
                                         : raw;
    st.bounds = samples.bounds;
    return st;
}

SurfaceStatistics wholeSurfaceStatistics(ProcessGroup& group, const core::SurfaceMesh& piece,
                                         const std::string& fieldName, const CommonParams& params) {
    StatisticsSamples s = statisticsSamples(piece, fieldName, params);
    s.speed = group.gather(s.speed);
    if (!params.colorBy.empty()) s.color = group.gather(s.color);
    if (!params.maskBy.empty()) s.mask = group.gather(s.mask);
    float box[6] = {s.bounds.lo.x, s.bounds.lo.y, s.bounds.lo.z, -s.bounds.hi.x, -s.bounds.hi.y, -s.bounds.hi.z};
    group.minInPlace(box);
    s.bounds.lo = {box[0], box[1], box[2]};
    s.bounds.hi = {-box[3], -box[4], -box[5]};
    SurfaceStatistics st = summarize(s, params);
    // The count in two floats, each exact (< 2^24), so that any surface sums exactly.
    const size_t own = piece.triangleCount();
    const float parts[2] = {float(own >> 20), float(own & ((size_t(1) << 20) - 1))};
    const std::vector<float> counts = group.gather(parts);
    for (size_t i = 0; i + 1 < counts.size(); i += 2) st.triangles += (size_t(counts[i]) << 20) + size_t(counts[i + 1]);
    return st;
}

glm::vec2 dataColorRange(const core::SurfaceMesh& mesh, const std::string& fieldName, const CommonParams& params) {
    return summarize(statisticsSamples(mesh, fieldName, params), params).colorRange;
}

std::vector<float> SurfaceGpu::interleave(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                          const CommonParams& params, const SurfaceStatistics* whole) {
    const core::VectorField* field = mesh.findField(fieldName);
    if (!field) throw FieldError("no vector field '" + fieldName + "'");
    std::vector<glm::vec3> vel;
    std::vector<float> speed = tangentialSpeed(mesh, *field, &vel);
    // This piece's samples (speed, colour and mask scalars), computed once: the statistics
    // of a whole mesh, and the per-vertex colour and mask values.
    StatisticsSamples own;
    own.speed = speed;
    if (!params.colorBy.empty()) own.color = scalarValues(mesh, params.colorBy);
    if (!params.maskBy.empty()) own.mask = scalarValues(mesh, params.maskBy);
    own.bounds = mesh.bounds();
    const SurfaceStatistics st = whole ? *whole : summarize(own, params);
    colorSpeedMax_ = st.speedP98;
    lineField_ = core::isLineField(fieldName);
    // Colour value: speed (0 .. p98 as before) or the --color-by scalar, over the given
    // range or the data's.
    std::vector<float> color = params.colorBy.empty() ? speed : std::move(own.color);
    colorName_ = params.colorBy.empty() ? "|" + fieldName + "|" : params.colorBy;
    colorRange_ = st.colorRange;
    normalizeInPlace(color, colorRange_);
    // Mask value: the --mask-by scalar, else speed / p98 (the velocity mask).
    std::vector<float> mask;
    if (!params.maskBy.empty()) {
        mask = std::move(own.mask);
        normalizeInPlace(mask, st.maskRange);
        for (float& m : mask) m = std::isfinite(m) ? std::clamp(m, 0.0f, 1.0f) : 0.0f;
    } else {
        mask = speed;
        normalizeInPlace(mask, {0.0f, colorSpeedMax_});
    }
    const float clampSpeed = st.clampSpeed;
    clampSpeed_ = params.normalize ? 0.0f : clampSpeed;
    std::vector<float> interleaved;
    interleaved.reserve(mesh.vertexCount() * kVertexFloats);
    for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        glm::vec3 v = vel[i];
        if (params.normalize && speed[i] > 0.0f) v /= speed[i];
        else if (clampSpeed > 0.0f && speed[i] > clampSpeed) v *= clampSpeed / speed[i];
        const glm::vec3& p = mesh.positions[i];
        const glm::vec3& n = mesh.normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z, v.x, v.y, v.z, color[i], mask[i], 0.0f});
    }
    maxSpeed_ = st.maxSpeed;
    bounds_ = st.bounds;
    positionSamples_.clear();
    const size_t stride = std::max<size_t>(1, (mesh.vertexCount() + kPositionSamples - 1) / kPositionSamples);
    for (size_t i = 0; i < mesh.vertexCount(); i += stride) positionSamples_.push_back(mesh.positions[i]);
    return interleaved;
}

bool SurfaceGpu::updateVertices(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                const CommonParams& params, const SurfaceStatistics* whole) {
    if (GLsizeiptr(mesh.vertexCount() * kVertexStride) != vertices_.size() ||
        mesh.triangleCount() != triangles_)
        return false;
    std::vector<float> interleaved = interleave(mesh, fieldName, params, whole);
    glNamedBufferSubData(vertices_.id(), 0, vertices_.size(), interleaved.data());
    generation_ = nextGeneration++;
    return true;
}

SurfaceGpu::SurfaceGpu(const core::SurfaceMesh& mesh, const std::string& fieldName, const CommonParams& params,
                       bool withEdges, const SurfaceStatistics* whole) {
    std::vector<float> interleaved = interleave(mesh, fieldName, params, whole);
    triangles_ = mesh.triangleCount();
    wholeTriangles_ = whole && whole->triangles ? whole->triangles : triangles_;
    // An empty piece (a process of a parallel render holding no triangles) draws nothing;
    // GL buffers need at least one byte.
    interleaved.resize(std::max<size_t>(interleaved.size(), kVertexFloats));
    vertices_ = gl::Buffer(GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_DYNAMIC_STORAGE_BIT);
    const glm::uvec3 none{0, 0, 0};
    indices_ = gl::Buffer(GLsizeiptr(std::max<size_t>(mesh.triangles.size(), 1) * sizeof(glm::uvec3)),
                          mesh.triangles.empty() ? &none : mesh.triangles.data(), 0);
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (interleaved.size() / 4 <= size_t(maxTexels) && std::max<size_t>(triangles_, 1) <= size_t(maxTexels)) {
        vertexTexture_ = gl::BufferTexture(GL_RGBA32F, vertices_);
        triangleTexture_ = gl::BufferTexture(GL_RGB32UI, indices_);
    }
    vao_ = gl::VertexArray::create();
    GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, kVertexStride);
    glVertexArrayElementBuffer(vao, indices_.id());
    // 0: position, 1: normal, 2: advection velocity (P-space), 3: colour value, 4: mask value.
    for (GLuint a = 0; a < 5; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, a < 3 ? 3 : 1, GL_FLOAT, GL_FALSE, (a < 4 ? a * 3 : 10) * sizeof(float));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    if (withEdges) {
        std::vector<uint32_t> edges = edgeAdjacency(mesh.triangles);
        edgeCount_ = edges.size() / 4;
        edgeIndices_ = gl::Buffer(GLsizeiptr(edges.size() * sizeof(uint32_t)), edges.data(), 0);
        edgeVao_ = gl::VertexArray::create();
        glVertexArrayVertexBuffer(edgeVao_.id(), 0, vertices_.id(), 0, kVertexStride);
        glVertexArrayElementBuffer(edgeVao_.id(), edgeIndices_.id());
        glEnableVertexArrayAttrib(edgeVao_.id(), 0);
        glVertexArrayAttribFormat(edgeVao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(edgeVao_.id(), 0, 0);
    }
    generation_ = nextGeneration++;
}

void SurfaceGpu::drawEdgesAdjacency() const {
    if (!edgeCount_) return;
    glBindVertexArray(edgeVao_.id());
    glDrawElements(GL_LINES_ADJACENCY, GLsizei(edgeCount_ * 4), GL_UNSIGNED_INT, nullptr);
}

void SurfaceGpu::draw() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, GLsizei(triangles_ * 3), GL_UNSIGNED_INT, nullptr);
}

void SurfaceGpu::drawInPieces(int pieces) const {
    glBindVertexArray(vao_.id());
    const size_t n = size_t(std::max(pieces, 1));
    for (size_t k = 0; k < n; ++k) {
        const size_t first = triangles_ * k / n, end = triangles_ * (k + 1) / n;
        glDrawElements(GL_TRIANGLES, GLsizei((end - first) * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(first * 3 * sizeof(uint32_t)));
        if (k + 1 < n) glFlush();
    }
}

}  // namespace flowsurf::methods
