#include "methods/isa/texture_advection.h"

#include <vector>

namespace flowsurf::methods::isa {

TextureAdvection::TextureAdvection(int gridRes)
    : gridRes_(gridRes),
      vao_(gl::VertexArray::create()),
      program_({{GL_VERTEX_SHADER, "isa/texture_advection.vert"}, {GL_FRAGMENT_SHADER, "isa/texture_advection.frag"}}) {
    std::vector<uint32_t> idx;
    idx.reserve(size_t(gridRes) * gridRes * 6);
    const uint32_t row = uint32_t(gridRes + 1);
    for (uint32_t j = 0; j < uint32_t(gridRes); ++j)
        for (uint32_t i = 0; i < uint32_t(gridRes); ++i) {
            uint32_t a = j * row + i;
            idx.insert(idx.end(), {a, a + 1, a + row + 1, a, a + row + 1, a + row});
        }
    indexCount_ = GLsizei(idx.size());
    indices_ = gl::Buffer(GLsizeiptr(idx.size() * sizeof(uint32_t)), idx.data(), 0);
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
}

void TextureAdvection::apply(const gl::Buffer& meshVertices, const gl::Texture2D& prevFlow,
                             const gl::Framebuffer& nextFlow, bool edgeBlending, float gray) const {
    glBindFramebuffer(GL_FRAMEBUFFER, nextFlow.id());
    glViewport(0, 0, prevFlow.width(), prevFlow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glVertexArrayVertexBuffer(vao_.id(), 0, meshVertices.id(), 0, 4 * sizeof(float));
    program_.use();
    glUniform1i(program_.uniform("uGridRes"), gridRes_);
    glUniform1i(program_.uniform("uEdgeBlending"), edgeBlending);
    glUniform1f(program_.uniform("uGray"), gray);
    glBindTextureUnit(0, prevFlow.id());
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace flowsurf::methods::isa
