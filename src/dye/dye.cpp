#include "dye/dye.h"

#include "core/errors.h"
#include "gpu/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace flowsurf::methods {

DyeField::DyeField(const core::SurfaceMesh& mesh, const std::string& field, const core::Bounds& bounds, float h,
                   ProcessGroup* group, bool divide)
    : shared_(group && group->size() > 1 ? std::make_unique<SharedDyeBand>(*group, mesh, makeDyeGrid(bounds, h))
                                         : nullptr),
      divided_(shared_ && divide),
      band_(shared_ ? shared_->takeBand() : buildDyeBand(mesh, makeDyeGrid(bounds, h))),
      positions_(mesh.positions),
      triangles_(mesh.triangles),
      program_(program({{GL_COMPUTE_SHADER, "dye/dye_advect.comp"}})) {
    const DyeGrid& g = band_.grid;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    indexTexture_ = gl::Handle<gl::detail::deleteTexture>(id);
    glTextureStorage3D(id, 1, GL_R32I, g.dims.x, g.dims.y, g.dims.z);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureSubImage3D(id, 0, 0, 0, 0, g.dims.x, g.dims.y, g.dims.z, GL_RED_INTEGER, GL_INT, band_.index.data());
    const size_t n = std::max<size_t>(band_.size(), 1);
    try {
        bandData_ = gl::Buffer(GLsizeiptr(n * 2 * sizeof(glm::vec4)), nullptr);
        values_ = gl::Buffer(GLsizeiptr(n * 3 * sizeof(glm::vec4)), nullptr);
        departures_ = gl::Buffer(GLsizeiptr(n * 2 * sizeof(glm::vec4)), nullptr);
        active_ = gl::Buffer(GLsizeiptr(n * sizeof(uint32_t)), nullptr);
        flags_ = gl::Buffer(GLsizeiptr((band_.brickStart.size()) * sizeof(uint32_t)), nullptr);
    } catch (const GlError& e) {
        throw GlError(std::string("dye: the band of ") + std::to_string(band_.size()) + " voxels: " + e.what());
    }
    setVelocity(mesh, field);
    clear();
}

bool DyeField::sameGeometry(const core::SurfaceMesh& mesh) const {
    if (mesh.triangles != triangles_ || mesh.positions.size() != positions_.size()) return false;
    // Interpolating two steps of a fixed mesh rounds the positions: a tenth of a voxel is
    // the same geometry (measured from the band's own positions, so a slow drift adds up).
    const float tolerance2 = 0.01f * band_.grid.h * band_.grid.h;
    for (size_t i = 0; i < positions_.size(); ++i) {
        const glm::vec3 d = mesh.positions[i] - positions_[i];
        if (glm::dot(d, d) > tolerance2) return false;
    }
    return true;
}

void DyeField::setVelocity(const core::SurfaceMesh& mesh, const std::string& field) {
    const std::vector<glm::vec3> vel = shared_ ? shared_->velocity(mesh, field) : bandVelocity(band_, mesh, field);
    std::vector<glm::vec4> data(std::max<size_t>(band_.size(), 1) * 2, glm::vec4(0.0f));
    maxSpeed_ = 0.0f;
    for (size_t i = 0; i < band_.size(); ++i) {
        data[2 * i] = glm::vec4(band_.closest[i], float(band_.brick[i]));  // brick: exact below 2^24
        data[2 * i + 1] = glm::vec4(vel[i], 0.0f);
        maxSpeed_ = std::max(maxSpeed_, glm::length(vel[i]));
    }
    glNamedBufferSubData(bandData_.id(), 0, GLsizeiptr(data.size() * sizeof(glm::vec4)), data.data());
    departureDt_ = 0.0f;
}

void DyeField::clear() {
    const float zero = 0.0f;
    glClearNamedBufferData(values_.id(), GL_R32F, GL_RED, GL_FLOAT, &zero);
    current_ = 0;
    hadDye_.assign(band_.brickStart.size() - 1, 0);
    hadDyeBefore_ = hadDye_;
    haloHeld_[0].assign(hadDye_.size(), 0);
    haloHeld_[1] = haloHeld_[0];
}

std::vector<uint8_t> DyeField::advectedBricks() const {
    return divided_ ? shared_->pieceBricks(shared_->group().rank()) : std::vector<uint8_t>(hadDye_.size(), 1);
}

void DyeField::pass(int which, float dt, float decayFactor, int emitterCount, int count) {
    const int n = int(band_.size());
    glUniform1i(program_.uniform("uPass"), which);
    glUniform1i(program_.uniform("uCount"), count);
    glUniform1i(program_.uniform("uUseList"), which != 3);
    glUniform1i(program_.uniform("uSource"), current_ * n);
    glUniform1i(program_.uniform("uForward"), 2 * n);
    glUniform1i(program_.uniform("uTarget"), (1 - current_) * n);
    glUniform1f(program_.uniform("uDt"), dt);
    glUniform1f(program_.uniform("uDecay"), decayFactor);
    glUniform1i(program_.uniform("uEmitters"), emitterCount);
    glDispatchCompute(GLuint((count + kDyeGroup - 1) / kDyeGroup), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

DyeField::Active DyeField::listActive(float dt, const std::vector<DyeEmitter>& emitters, int readReach) {
    const glm::ivec3 bd = band_.brickDims;
    const float brickSize = float(kDyeBrick) * band_.grid.h;
    Active out;
    out.bricks.assign(hadDye_.size(), 0);
    auto brickOf = [&](const glm::vec3& p) {
        return glm::clamp(glm::ivec3(glm::floor((p - band_.grid.origin) / brickSize)), glm::ivec3(0), bd - 1);
    };
    auto mark = [&](glm::ivec3 lo, glm::ivec3 hi) {
        lo = glm::max(lo, glm::ivec3(0));
        hi = glm::min(hi, bd - 1);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    out.bricks[(size_t(z) * size_t(bd.y) + size_t(y)) * size_t(bd.x) + size_t(x)] = 1;
    };
    // Reach of one step: the forward and the backward departure point, and the stencil.
    const int reach = int(std::ceil((2.0f * maxSpeed_ * std::abs(dt) + 2.0f * band_.grid.h) / brickSize));
    for (int z = 0; z < bd.z; ++z)
        for (int y = 0; y < bd.y; ++y)
            for (int x = 0; x < bd.x; ++x) {
                const size_t b = (size_t(z) * size_t(bd.y) + size_t(y)) * size_t(bd.x) + size_t(x);
                if (hadDye_[b] || hadDyeBefore_[b]) mark(glm::ivec3(x, y, z) - reach, glm::ivec3(x, y, z) + reach);
            }
    for (const DyeEmitter& e : emitters) {
        const glm::vec3 r(e.radius + 2.0f * band_.grid.h);
        mark(brickOf(e.posObj - r), brickOf(e.posObj + r));
    }
    const std::vector<uint8_t> mine = advectedBricks();
    const std::vector<uint8_t> forward = divided_ ? dilateBoth(mine, out.bricks, bd, readReach) : out.bricks;
    std::vector<uint32_t> list, more;
    for (size_t b = 0; b < out.bricks.size(); ++b) {
        if (!out.bricks[b]) continue;
        out.any = true;
        std::vector<uint32_t>* to = mine[b] ? &list : forward[b] ? &more : nullptr;
        if (to)
            for (uint32_t i = band_.brickStart[b]; i < band_.brickStart[b + 1]; ++i) to->push_back(i);
    }
    out.advected = list.size();
    list.insert(list.end(), more.begin(), more.end());
    out.forward = list.size();
    if (!list.empty())
        glNamedBufferSubData(active_.id(), 0, GLsizeiptr(list.size() * sizeof(uint32_t)), list.data());
    return out;
}

void DyeField::receiveHalo(const std::vector<uint8_t>& active, int readReach) {
    ProcessGroup& group = shared_->group();
    const int me = group.rank(), n = group.size();
    const glm::ivec3 bd = band_.brickDims;
    const size_t slot = size_t(current_) * band_.size();
    auto voxels = [&](size_t b) { return size_t(band_.brickStart[b + 1] - band_.brickStart[b]); };
    auto offset = [&](size_t b) { return GLintptr((slot + band_.brickStart[b]) * sizeof(glm::vec4)); };
    // What process q reads and does not advect: within twice the reach of its active bricks
    // (pass 0 runs up to one reach from them and reads one reach further).
    auto halo = [&](int q) { return dilateBoth(shared_->pieceBricks(q), active, bd, 2 * readReach); };
    std::vector<std::vector<uint8_t>> sends(static_cast<size_t>(n));
    for (int q = 0; q < n; ++q) {
        if (q == me) continue;
        const std::vector<uint8_t> wanted = halo(q);
        const std::vector<uint8_t>& theirs = shared_->pieceBricks(q);
        std::vector<uint8_t>& out = sends[size_t(q)];
        // Runs of consecutive bricks are consecutive voxels: one read-back per run.
        const auto sent = [&](size_t b) { return wanted[b] && !theirs[b] && hadDye_[b] && shared_->keeper(b) == me; };
        for (size_t b = 0; b < wanted.size(); ++b) {
            if (!sent(b)) continue;
            size_t end = b + 1;
            while (end < wanted.size() && sent(end)) ++end;
            const size_t at = out.size();
            const size_t bytes = size_t(band_.brickStart[end] - band_.brickStart[b]) * sizeof(glm::vec4);
            out.resize(at + bytes);
            glGetNamedBufferSubData(values_.id(), offset(b), GLsizeiptr(bytes), out.data() + at);
            b = end - 1;
        }
        haloBytesSent_ += out.size();
    }
    const std::vector<std::vector<uint8_t>> in = group.exchange(sends);
    const std::vector<uint8_t> wanted = halo(me);
    const std::vector<uint8_t>& mine = shared_->pieceBricks(me);
    std::vector<size_t> read(size_t(n), 0);
    std::vector<uint8_t>& held = haloHeld_[current_];
    const glm::vec4 zero(0.0f);
    for (size_t b = 0; b < wanted.size(); ++b) {
        if (!wanted[b] || mine[b]) continue;
        const size_t bytes = voxels(b) * sizeof(glm::vec4);
        if (hadDye_[b]) {
            const size_t q = size_t(shared_->keeper(b));
            if (read[q] + bytes > in[q].size())
                throw Error("dye: process " + std::to_string(q) + " sent a shorter halo than this one reads");
            glNamedBufferSubData(values_.id(), offset(b), GLsizeiptr(bytes), in[q].data() + read[q]);
            read[q] += bytes;
            held[b] = 1;
        } else if (held[b]) {
            glClearNamedBufferSubData(values_.id(), GL_RGBA32F, offset(b), GLsizeiptr(bytes), GL_RGBA, GL_FLOAT,
                                      glm::value_ptr(zero));
            held[b] = 0;
        }
    }
    for (int q = 0; q < n; ++q)
        if (read[size_t(q)] != in[size_t(q)].size())
            throw Error("dye: process " + std::to_string(q) + " sent a longer halo than this one reads");
}

void DyeField::step(float dt, float decay, const std::vector<DyeEmitter>& emitters) {
    advectedVoxels_ = haloBytesSent_ = 0;
    if (band_.size() == 0) return;
    // How far from a voxel a pass reads: its closest point (up to the band's radius away),
    // one step along the surface, the stencil around the departure point.
    const float reachObj = maxSpeed_ * std::abs(dt) + (kDyeBandVoxels + 2.0f) * band_.grid.h;
    const int readReach = int(std::ceil(reachObj / (float(kDyeBrick) * band_.grid.h)));
    const Active active = listActive(dt, emitters, readReach);
    if (!active.any) return;  // no dye anywhere, none released (the same on every process)
    advectedVoxels_ = active.advected;
    std::vector<glm::vec4> e;
    for (const DyeEmitter& d : emitters) {
        e.emplace_back(d.posObj, d.radius);
        e.emplace_back(d.color, 1.0f);
    }
    if (e.empty()) e.emplace_back(0.0f);  // a buffer must have storage
    emitters_ = gl::Buffer(GLsizeiptr(e.size() * sizeof(glm::vec4)), e.data());
    const uint32_t zero = 0;
    glClearNamedBufferData(flags_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    const bool moving = dt != 0.0f && maxSpeed_ > 0.0f;
    if (moving && divided_) receiveHalo(active.bricks, readReach);
    program_.use();
    const DyeGrid& g = band_.grid;
    glUniform3fv(program_.uniform("uDyeOrigin"), 1, glm::value_ptr(g.origin));
    glUniform1f(program_.uniform("uDyeH"), g.h);
    glBindTextureUnit(bindings::kDyeIndex, indexTexture_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeValue, values_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeBand, bandData_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeSource, emitters_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeDeparture, departures_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeFlag, flags_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeActive, active_.id());
    const float decayFactor = std::exp(-std::max(decay, 0.0f) * std::abs(dt));
    const int emitterCount = int(emitters.size());
    if (moving) {
        if (dt != departureDt_) {
            pass(3, dt, decayFactor, 0, int(band_.size()));
            departureDt_ = dt;
        }
        pass(0, dt, decayFactor, 0, int(active.forward));
        pass(1, dt, decayFactor, emitterCount, int(active.advected));
        pass(4, dt, decayFactor, 0, int(active.forward));
    } else {
        pass(2, dt, decayFactor, emitterCount, int(active.advected));
    }
    current_ = 1 - current_;
    // Where dye is now: the next step's bricks (a small read-back, once per frame; divided,
    // every process's own bricks combined).
    hadDyeBefore_.swap(hadDye_);
    glGetNamedBufferSubData(flags_.id(), 0, GLsizeiptr(hadDye_.size() * sizeof(uint32_t)), hadDye_.data());
    if (divided_) {
        std::vector<int32_t> none(hadDye_.size());
        for (size_t b = 0; b < none.size(); ++b) none[b] = hadDye_[b] ? 0 : 1;
        shared_->group().minInPlace(std::span<int32_t>(none));
        for (size_t b = 0; b < none.size(); ++b) hadDye_[b] = none[b] ? 0 : 1;
    }
}

DyeView DyeField::view(const core::Camera& camera, const core::Viewport& viewport) const {
    DyeView v;
    v.index = indexTexture_.id();
    v.values = values_.id();
    v.slot = current_ * int(band_.size());
    v.grid = band_.grid;
    v.invViewProj = glm::inverse(camera.viewProjection(viewport.aspect()));
    return v;
}

std::vector<glm::vec4> DyeField::readValues() const {
    std::vector<glm::vec4> out(band_.size());
    if (!out.empty())
        glGetNamedBufferSubData(values_.id(), GLintptr(size_t(current_) * band_.size() * sizeof(glm::vec4)),
                                GLsizeiptr(out.size() * sizeof(glm::vec4)), out.data());
    return out;
}

}  // namespace flowsurf::methods
