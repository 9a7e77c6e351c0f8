#include "mapper_composite.h"

#include "gpu/shader_interface.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace flowsurf::paraview {

void MapperComposite::release()
{
  composite_ = {};
  compositeHost_ = {};
  emptyVao_ = {};
  hostTable_ = {};
  hostTableColors_.clear();
}

void MapperComposite::draw(const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::PixelRect& piece,
  const methods::FlowMethod& method, const HostLook* host, bool blend, glm::vec2 valueRange)
{
  if (emptyVao_.id() == 0)
  {
    emptyVao_ = gl::VertexArray::create();
  }
  gl::Program& program = host ? compositeHost_ : composite_;
  if (!program)
  {
    program = methods::program(
      { { GL_VERTEX_SHADER, "gpu/fullscreen.vert" }, { GL_FRAGMENT_SHADER, "paraview/composite.frag" } },
      host ? "#define HOST_LOOK 1\n#define MAX_LIGHTS " + std::to_string(kMaxHostLights) + "\n" : std::string());
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, guard.drawFramebuffer());
  glViewport(x0, y0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  // Without ParaView's pass the surface's depth is ours to write, for what is drawn after.
  glDepthMask(host ? GL_TRUE : GL_FALSE);
  if (blend && !host)
  {
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);  // ParaView's colour x the method's image
  }
  else
  {
    glDisable(GL_BLEND);
  }
  if (piece.empty())
  {
    return;
  }
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0 + piece.x0, y0 + piece.y0, piece.width(), piece.height());
  program.use();
  glUniform2i(program.uniform("uOrigin"), x0, y0);
  glUniform1f(program.uniform("uDepthBias"), 2e-5f);
  glBindTextureUnit(methods::bindings::kCompositeColor, method.composite().id());
  glBindTextureUnit(methods::bindings::kCompositeDepth, method.surfaceDepth().id());
  if (host)
  {
    glBindTextureUnit(methods::bindings::kCompositeShade, method.surfaceShade().id());
    setHostLook(program, *host, blend, valueRange);
  }
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);
}

void MapperComposite::setHostLook(const gl::Program& program, const HostLook& look, bool blend, glm::vec2 valueRange)
{
  if (!hostTable_ || look.table != hostTableColors_)
  {
    if (!hostTable_)
    {
      hostTable_ = gl::Texture2D(GL_RGBA8, 256, 1, GL_LINEAR);
    }
    std::vector<unsigned char> rgba(256 * 4, 255);
    for (size_t i = 0; i < look.table.size() && i < 256; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgba[i * 4 + size_t(c)] = (unsigned char)std::lround(std::clamp(look.table[i][c], 0.0f, 1.0f) * 255.0f);
      }
    }
    glTextureSubImage2D(hostTable_.id(), 0, 0, 0, 256, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    hostTableColors_ = look.table;
  }
  glBindTextureUnit(methods::bindings::kCompositeTable, hostTable_.id());
  glUniform1i(program.uniform("uMultiply"), blend);
  glUniform1i(program.uniform("uScalars"), look.scalars.has_value());
  glUniform2f(program.uniform("uValueRange"), valueRange.x, valueRange.y);
  glUniform2f(program.uniform("uTableRange"), look.range.x, look.range.y);
  glUniform3f(program.uniform("uSolid"), look.solid.x, look.solid.y, look.solid.z);
  glUniform3f(program.uniform("uNanColor"), look.nanColor.x, look.nanColor.y, look.nanColor.z);
  glUniform1i(program.uniform("uLighting"), look.lighting);
  glUniform1f(program.uniform("uAmbient"), look.ambient);
  glUniform1f(program.uniform("uDiffuse"), look.diffuse);
  const GLsizei lights = GLsizei(look.lightDirEye.size());
  glUniform1i(program.uniform("uLightCount"), lights);
  if (lights > 0)
  {
    glUniform3fv(program.uniform("uLightDir"), lights, &look.lightDirEye[0].x);
    glUniform3fv(program.uniform("uLightColor"), lights, &look.lightColor[0].x);
  }
}

}  // namespace flowsurf::paraview
