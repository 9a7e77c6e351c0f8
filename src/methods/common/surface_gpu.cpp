#include "methods/common/surface_gpu.h"

#include "core/errors.h"

#include <atomic>
#include <vector>

namespace flowsurf::methods {

namespace {
std::atomic<uint64_t> nextGeneration{1};
}

std::string selectField(const core::SurfaceMesh& mesh, const std::string& requested, const std::string& where) {
    if (mesh.fields.empty())
        throw FieldError(where + ": no 3-component point array to use as the vector field");
    if (requested.empty()) return mesh.fields.front().name;
    if (mesh.findField(requested)) return requested;
    std::string names;
    for (const auto& f : mesh.fields) names += (names.empty() ? "" : ", ") + f.name;
    throw FieldError(where + ": no vector field '" + requested + "' (available: " + names + ")");
}

SurfaceGpu::SurfaceGpu(const core::SurfaceMesh& mesh, const std::string& fieldName) {
    const core::VectorField* field = mesh.findField(fieldName);
    if (!field) throw FieldError("no vector field '" + fieldName + "'");
    std::vector<glm::vec3> vel = field->values;
    core::makeTangential(vel, mesh.normals);
    std::vector<float> interleaved;
    interleaved.reserve(mesh.vertexCount() * 9);
    for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        for (const glm::vec3* v : {&mesh.positions[i], &mesh.normals[i], static_cast<const glm::vec3*>(&vel[i])})
            interleaved.insert(interleaved.end(), {v->x, v->y, v->z});
        maxSpeed_ = std::max(maxSpeed_, glm::length(vel[i]));
    }
    bounds_ = mesh.bounds();
    triangles_ = mesh.triangleCount();
    vertices_ = gl::Buffer(GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), 0);
    indices_ = gl::Buffer(GLsizeiptr(mesh.triangles.size() * sizeof(glm::uvec3)), mesh.triangles.data(), 0);
    vao_ = gl::VertexArray::create();
    GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, 9 * sizeof(float));
    glVertexArrayElementBuffer(vao, indices_.id());
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    generation_ = nextGeneration++;
}

void SurfaceGpu::draw() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, GLsizei(triangles_ * 3), GL_UNSIGNED_INT, nullptr);
}

}  // namespace flowsurf::methods
