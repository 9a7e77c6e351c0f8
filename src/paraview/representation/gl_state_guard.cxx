#include "gl_state_guard.h"

#include "vtkOpenGLState.h"

namespace flowsurf::paraview {

GlStateGuard::GlStateGuard(vtkOpenGLState* state)
  : state_(state)
{
  state_->Push();
  state_->PushFramebufferBindings();
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer_);
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer_);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  for (int u = 0; u < kUnits; ++u)
  {
    glActiveTexture(GL_TEXTURE0 + u);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &tex2d_[u]);
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &tex3d_[u]);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler_[u]);
  }
  // The defaults flowsurf's passes were written against (a fresh context).
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

GlStateGuard::~GlStateGuard()
{
  for (int u = 0; u < kUnits; ++u)
  {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, tex2d_[u]);
    glBindTexture(GL_TEXTURE_3D, tex3d_[u]);
    glBindSampler(u, sampler_[u]);
  }
  glActiveTexture(activeTexture_);
  glUseProgram(program_);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ARRAY_BUFFER, arrayBuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, packBuffer_);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpackBuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, drawFramebuffer_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer_);
  // VTK's cache is unchanged; make GL match it again.
  state_->PopFramebufferBindings();
  state_->Pop();
}

}  // namespace flowsurf::paraview
