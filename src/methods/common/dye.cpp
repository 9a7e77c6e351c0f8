#include "methods/common/dye.h"

#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::methods {

DyeField::DyeField(const core::SurfaceMesh& mesh, const std::string& field, float h)
    : band_(buildDyeBand(mesh, makeDyeGrid(mesh.bounds(), h))),
      positions_(mesh.positions),
      triangles_(mesh.triangles),
      program_(program({{GL_COMPUTE_SHADER, "common/dye_advect.comp"}})) {
    const DyeGrid& g = band_.grid;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    indexTexture_ = gl::Handle<gl::detail::deleteTexture>(id);
    glTextureStorage3D(id, 1, GL_R32I, g.dims.x, g.dims.y, g.dims.z);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureSubImage3D(id, 0, 0, 0, 0, g.dims.x, g.dims.y, g.dims.z, GL_RED_INTEGER, GL_INT, band_.index.data());
    const size_t n = std::max<size_t>(band_.size(), 1);
    bandData_ = gl::Buffer(GLsizeiptr(n * 2 * sizeof(glm::vec4)), nullptr);
    values_ = gl::Buffer(GLsizeiptr(n * 3 * sizeof(glm::vec4)), nullptr);
    departures_ = gl::Buffer(GLsizeiptr(n * 2 * sizeof(glm::vec4)), nullptr);
    setVelocity(mesh, field);
    clear();
}

bool DyeField::sameGeometry(const core::SurfaceMesh& mesh) const {
    return mesh.positions == positions_ && mesh.triangles == triangles_;
}

void DyeField::setVelocity(const core::SurfaceMesh& mesh, const std::string& field) {
    const std::vector<glm::vec3> vel = bandVelocity(band_, mesh, field);
    std::vector<glm::vec4> data(std::max<size_t>(band_.size(), 1) * 2, glm::vec4(0.0f));
    maxSpeed_ = 0.0f;
    for (size_t i = 0; i < band_.size(); ++i) {
        data[2 * i] = glm::vec4(band_.closest[i], 0.0f);
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
}

void DyeField::pass(int which, float dt, float decayFactor, int emitterCount) {
    const int n = int(band_.size());
    glUniform1i(program_.uniform("uPass"), which);
    glUniform1i(program_.uniform("uCount"), n);
    glUniform1i(program_.uniform("uSource"), current_ * n);
    glUniform1i(program_.uniform("uForward"), 2 * n);
    glUniform1i(program_.uniform("uTarget"), (1 - current_) * n);
    glUniform1f(program_.uniform("uDt"), dt);
    glUniform1f(program_.uniform("uDecay"), decayFactor);
    glUniform1i(program_.uniform("uEmitters"), emitterCount);
    glDispatchCompute(GLuint((n + kDyeGroup - 1) / kDyeGroup), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void DyeField::step(float dt, float decay, const std::vector<DyeEmitter>& emitters) {
    if (band_.size() == 0) return;
    std::vector<glm::vec4> e;
    for (const DyeEmitter& d : emitters) {
        e.emplace_back(d.posObj, d.radius);
        e.emplace_back(d.color, 1.0f);
    }
    if (e.empty()) e.emplace_back(0.0f);  // a buffer must have storage
    emitters_ = gl::Buffer(GLsizeiptr(e.size() * sizeof(glm::vec4)), e.data());
    program_.use();
    const DyeGrid& g = band_.grid;
    glUniform3fv(program_.uniform("uDyeOrigin"), 1, glm::value_ptr(g.origin));
    glUniform1f(program_.uniform("uDyeH"), g.h);
    glBindTextureUnit(kDyeIndexUnit, indexTexture_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDyeValueBinding, values_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDyeBandBinding, bandData_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDyeSourceBinding, emitters_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDyeDepartureBinding, departures_.id());
    const float decayFactor = std::exp(-std::max(decay, 0.0f) * std::abs(dt));
    if (dt != 0.0f && maxSpeed_ > 0.0f) {
        if (dt != departureDt_) {
            pass(3, dt, decayFactor, 0);
            departureDt_ = dt;
        }
        pass(0, dt, decayFactor, 0);
        pass(1, dt, decayFactor, int(emitters.size()));
    } else {
        pass(2, dt, decayFactor, int(emitters.size()));
    }
    current_ = 1 - current_;
    // The overlay reads the values next, in a fragment or compute shader.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
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
