#include "raster/surface_gpu.h"

#include "core/derived_fields.h"
#include "core/errors.h"
#include "gpu/shader_interface.h"
#include "parallel/screen_split.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>
#include <vector>

namespace flowsurf::methods {

namespace {
std::atomic<uint64_t> nextGeneration{1};

// Writes the `a.components` floats at `value` into attribute `a` of `vertex`.
void put(float* vertex, const VertexAttribute& a, const float* value) { std::copy_n(value, a.components, vertex + a.offset); }
}  // namespace

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
// Per edge: (v0, v1, opposite in the triangle with v0->v1, opposite in the other one);
// the one-sided edges listed in `seams` (sorted) left out.
std::vector<uint32_t> edgeAdjacency(const std::vector<glm::uvec3>& triangles, const std::vector<uint64_t>& seams) {
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
    if (seams.empty()) return out;
    std::vector<uint32_t> kept;
    kept.reserve(out.size());
    for (size_t e = 0; e < out.size(); e += 4) {
        const uint64_t key = (uint64_t(std::min(out[e], out[e + 1])) << 32) | std::max(out[e], out[e + 1]);
        if (out[e + 2] == out[e + 3] && std::binary_search(seams.begin(), seams.end(), key)) continue;
        kept.insert(kept.end(), out.begin() + long(e), out.begin() + long(e) + 4);
    }
    return kept;
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

// (v - lo) / (hi - lo), NaN kept; a flat range maps to 0 (as a zero speed did). Log:
// the same in log10, values <= 0 below the range. Clamped to +-kShadeLimit: the colour
// value travels in a half float (the G-buffer's shade), whose largest value is 65504.
constexpr float kShadeLimit = 60000.0f;
void normalizeInPlace(std::vector<float>& v, glm::vec2 range, ColorScale scale = ColorScale::Linear) {
    const bool log = scale == ColorScale::Log && range.x > 0.0f;
    const double lo = log ? std::log10(double(range.x)) : range.x, hi = log ? std::log10(double(range.y)) : range.y;
    const double span = hi - lo;
    for (float& x : v) {
        if (std::isnan(x)) continue;
        if (!(span > 0.0)) { x = 0.0f; continue; }
        const double t = log ? (x > 0.0f ? (std::log10(double(x)) - lo) / span : -1.0) : (double(x) - lo) / span;
        x = float(std::clamp(t, double(-kShadeLimit), double(kShadeLimit)));
    }
}

std::string rangeText(glm::vec2 r) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g:%g", double(r.x), double(r.y));
    return buf;
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
    s.area = core::vertexAreas(mesh);
    s.bounds = mesh.bounds();
    return s;
}

namespace {
// `r` grown by the finite values of `v`.
glm::vec2 unite(glm::vec2 r, const std::vector<float>& v) {
    auto [lo, hi] = core::finiteRange(v);
    if (lo > hi) return r;
    return r.x > r.y ? glm::vec2(lo, hi) : glm::vec2(std::min(r.x, lo), std::max(r.y, hi));
}
}  // namespace

// Only the robust ranges need the sorted distributions; a given or data range needs the
// extremes alone (a series' every upload sees its range given).
bool RangeAccumulator::robustColor() const {
    const CommonParams& p = params_;
    const bool given = p.colorRange.x <= p.colorRange.y && !p.colorRangeAuto;
    const bool robust = p.colorRangeMode == RangeMode::Robust && !p.colorRangeAuto;
    return !given && robust && (!p.colorBy.empty() || p.colorScale == ColorScale::Log);
}

bool RangeAccumulator::robustMask() const {
    const CommonParams& p = params_;
    return !p.maskBy.empty() && !(p.maskRange.x <= p.maskRange.y && !p.maskRangeAuto) && !p.maskRangeAuto &&
           p.maskRangeMode == RangeMode::Robust;
}

void RangeAccumulator::add(const StatisticsSamples& s) {
    speedP98_ = std::max(speedP98_, percentile(s.speed, 98.0f));
    const std::vector<float>& color = params_.colorBy.empty() ? s.speed : s.color;
    colorData_ = unite(colorData_, color);
    if (robustColor()) color_.add(color, s.area);
    if (params_.maskBy.empty()) return;
    maskData_ = unite(maskData_, s.mask);
    if (robustMask()) mask_.add(s.mask, s.area);
}

glm::vec2 RangeAccumulator::colorRange() const {
    const CommonParams& p = params_;
    const bool log = p.colorScale == ColorScale::Log;
    const std::string array = p.colorBy.empty() ? "the speed" : "'" + p.colorBy + "'";
    if (p.colorRange.x <= p.colorRange.y && !p.colorRangeAuto) {
        if (log && !(p.colorRange.x > 0.0f))
            throw ConfigError("--color-scale log: --color-range " + rangeText(p.colorRange) +
                              " is not positive (a log scale needs MIN > 0)");
        return p.colorRange;
    }
    const bool robust = robustColor();
    glm::vec2 r = robust ? core::robustRange(color_, log) : colorData_;
    // Speed keeps its range from before [doc/contrast.md]: 0 .. its 98th percentile (robust, auto).
    if (p.colorBy.empty() && !log && p.colorRangeMode == RangeMode::Robust) r = glm::vec2(0.0f, speedP98_);
    if (log && !(r.x > 0.0f && r.x <= r.y))
        throw ConfigError("--color-scale log: " + array + " is not positive over " +
                          (robust ? "a quarter or more of the surface" : "its range") + " (data range " +
                          rangeText(colorData_) + "): use --color-range MIN:MAX with MIN > 0, or "
                          "--color-scale linear");
    return r;
}

glm::vec2 RangeAccumulator::maskRange() const {
    const CommonParams& p = params_;
    if (p.maskRange.x <= p.maskRange.y && !p.maskRangeAuto) return p.maskRange;
    return robustMask() ? core::robustRange(mask_) : maskData_;
}

SurfaceStatistics summarize(const StatisticsSamples& samples, const CommonParams& params) {
    SurfaceStatistics st;
    RangeAccumulator ranges(params);
    ranges.add(samples);
    st.speedP98 = ranges.speedP98();
    st.colorRange = ranges.colorRange();
    st.colorDataRange = ranges.colorDataRange();
    if (!params.maskBy.empty()) st.maskRange = ranges.maskRange();
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
    s.area = group.gather(s.area);  // a vertex on a piece boundary: its share in each piece
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
    own.area = core::vertexAreas(mesh);
    own.bounds = mesh.bounds();
    const SurfaceStatistics st = whole ? *whole : summarize(own, params);
    colorSpeedMax_ = st.speedP98;
    lineField_ = core::isLineField(fieldName);
    // Colour value: speed (0 .. p98 as before) or the --color-by scalar, over the given
    // range or the data's.
    std::vector<float> color = params.colorBy.empty() ? speed : std::move(own.color);
    colorName_ = params.colorBy.empty() ? "|" + fieldName + "|" : params.colorBy;
    colorRange_ = st.colorRange;
    colorDataRange_ = st.colorDataRange;
    normalizeInPlace(color, colorRange_, params.colorScale);
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
    using namespace surface_vertex;
    std::vector<float> interleaved(mesh.vertexCount() * kFloats, 0.0f);  // the padding stays 0
    for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        glm::vec3 v = vel[i];
        if (params.normalize && speed[i] > 0.0f) v /= speed[i];
        else if (clampSpeed > 0.0f && speed[i] > clampSpeed) v *= clampSpeed / speed[i];
        float* vertex = interleaved.data() + i * kFloats;
        put(vertex, kPosObj, &mesh.positions[i].x);
        put(vertex, kNormalObj, &mesh.normals[i].x);
        put(vertex, kVelObj, &v.x);
        put(vertex, kColor, &color[i]);
        put(vertex, kMask, &mask[i]);
    }
    maxSpeed_ = st.maxSpeed;
    bounds_ = st.bounds;
    pieceParts_ = surfaceParts(mesh);
    positionSamples_.clear();
    const size_t stride = std::max<size_t>(1, (mesh.vertexCount() + kPositionSamples - 1) / kPositionSamples);
    for (size_t i = 0; i < mesh.vertexCount(); i += stride) positionSamples_.push_back(mesh.positions[i]);
    return interleaved;
}

bool SurfaceGpu::updateVertices(const core::SurfaceMesh& mesh, const std::string& fieldName,
                                const CommonParams& params, const SurfaceStatistics* whole) {
    if (GLsizeiptr(mesh.vertexCount() * surface_vertex::kStride) != vertices_.size() ||
        mesh.triangleCount() != triangles_)
        return false;
    std::vector<float> interleaved = interleave(mesh, fieldName, params, whole);
    glNamedBufferSubData(vertices_.id(), 0, vertices_.size(), interleaved.data());
    generation_ = nextGeneration++;
    return true;
}

SurfaceGpu::SurfaceGpu(const core::SurfaceMesh& mesh, const std::string& fieldName, const CommonParams& params,
                       bool withEdges, const SurfaceStatistics* whole, const PieceSeams* seams) {
    std::vector<float> interleaved = interleave(mesh, fieldName, params, whole);
    triangles_ = mesh.triangleCount();
    wholeTriangles_ = whole && whole->triangles ? whole->triangles : triangles_;
    // An empty piece (a process of a parallel render holding no triangles) draws nothing;
    // GL buffers need at least one byte.
    interleaved.resize(std::max<size_t>(interleaved.size(), surface_vertex::kFloats));
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
    glVertexArrayVertexBuffer(vao, surface_vertex::kBuffer, vertices_.id(), 0, surface_vertex::kStride);
    glVertexArrayElementBuffer(vao, indices_.id());
    for (const VertexAttribute& a : surface_vertex::kAttributes) enableAttribute(vao, a);
    if (withEdges) {
        std::vector<uint32_t> edges = edgeAdjacency(mesh.triangles, seams ? seams->edges : std::vector<uint64_t>{});
        edgeCount_ = edges.size() / 4;
        edgeIndices_ = gl::Buffer(GLsizeiptr(edges.size() * sizeof(uint32_t)), edges.data(), 0);
        edgeVao_ = gl::VertexArray::create();
        glVertexArrayVertexBuffer(edgeVao_.id(), surface_vertex::kBuffer, vertices_.id(), 0, surface_vertex::kStride);
        glVertexArrayElementBuffer(edgeVao_.id(), edgeIndices_.id());
        enableAttribute(edgeVao_.id(), surface_vertex::kPosObj);
        if (seams && !seams->drawn.empty()) {
            seamCount_ = seams->drawn.size();
            seamPositions_ = gl::Buffer(GLsizeiptr(seamCount_ * sizeof(AdjacentEdge)), seams->drawn.data(), 0);
            seamVao_ = gl::VertexArray::create();
            glVertexArrayVertexBuffer(seamVao_.id(), surface_vertex::kBuffer, seamPositions_.id(), 0, sizeof(glm::vec3));
            enableAttribute(seamVao_.id(), surface_vertex::kPosObj.alone());
        }
    }
    generation_ = nextGeneration++;
}

void SurfaceGpu::drawEdgesAdjacency() const {
    if (edgeCount_) {
        glBindVertexArray(edgeVao_.id());
        glDrawElements(GL_LINES_ADJACENCY, GLsizei(edgeCount_ * 4), GL_UNSIGNED_INT, nullptr);
    }
    if (seamCount_) {  // a piece's seams, the other side's vertex beside it (piece_seams.h)
        glBindVertexArray(seamVao_.id());
        glDrawArrays(GL_LINES_ADJACENCY, 0, GLsizei(seamCount_ * 4));
    }
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
