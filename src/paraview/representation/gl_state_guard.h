// flowsurf — saves the OpenGL state that VTK caches (vtkOpenGLState: enables, blend,
// depth, viewport, scissor, framebuffers) and the bindings it does not cache but
// assumes (program, vertex array, textures, pixel store), puts GL into the defaults
// flowsurf's passes expect, and restores everything on destruction.
#ifndef gl_state_guard_h
#define gl_state_guard_h

#include "gpu/gpu_bindings.h"

#include <epoxy/gl.h>

#include <array>

class vtkOpenGLState;

namespace flowsurf::paraview {

class GlStateGuard
{
public:
  explicit GlStateGuard(vtkOpenGLState* state);
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;
  GLuint drawFramebuffer() const { return drawFramebuffer_; }

private:
  // The texture units saved and restored: every one flowsurf's passes bind.
  static constexpr int kUnits = 16;
  static_assert(methods::highestPoint(methods::BindingPoint::Texture) < kUnits, "a texture unit the guard does not restore");
  vtkOpenGLState* state_;
  GLint program_ = 0, vertexArray_ = 0, activeTexture_ = 0, arrayBuffer_ = 0;
  GLint packAlignment_ = 4, unpackAlignment_ = 4, packBuffer_ = 0, unpackBuffer_ = 0;
  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
  std::array<GLint, kUnits> tex2d_{}, tex3d_{}, sampler_{};
};

}  // namespace flowsurf::paraview

#endif
