#include "mapper_topology.h"

#include "polydata_to_mesh.h"
#include "surface_gather.h"

#include "core/errors.h"
#include "gpu/gpu_bindings.h"
#include "gpu/shader_interface.h"

#include "vtkMultiProcessController.h"

#include <array>

namespace flowsurf::paraview {

namespace {

// The rows that decide the overlay: a change re-analyses (the analysis is cheap next to a
// frame's warm-up; the style rows could restyle only).
constexpr std::array kRows{ "topology", "topology-parts", "topology-scale", "topology-cancel-speed",
  "topology-line-strength", "topology-line-length", "topology-glyph-size", "topology-line-width",
  "reverse-field" };

std::string optionsKey(const session::RenderOptions& o)
{
  std::string key = o.field;
  for (const char* row : kRows)
  {
    key += '\n' + session::findOption(row)->get(o);
  }
  return key;
}

}  // namespace

void MapperTopology::update(core::StepProvider& steps, const session::RenderOptions& o, bool dataChanged, bool parallel)
{
  if (!o.topology)
  {
    shown_.reset();
    key_.clear();
    return;
  }
  const std::string key = optionsKey(o);
  if (!dataChanged && key == key_)
  {
    return;
  }
  key_ = key;
  shown_.reset();
  uploaded_ = false;
  style_.points = o.topologyParts != "lines";
  style_.lines = o.topologyParts != "points";
  style_.glyphSize = o.topologyGlyphSize;
  style_.lineWidth = o.topologyLineWidth;
  // analysed now: its error is this render's, once
  shown_ = parallel ? analyzeWhole(steps, o) : session::TopologySource(steps, o).at(0);
}

skeleton::Skeleton MapperTopology::analyzeWhole(core::StepProvider& steps, const session::RenderOptions& o)
{
  // The pieces gathered on process 0 (the analysis welds their shared vertices), analysed
  // there as one process analyses its surface, the result sent to all; collective, and an
  // error on process 0 is every process's.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  PieceSteps whole;
  whole.mesh = gatherToRoot(controller, steps.load(0));
  skeleton::Skeleton result;
  std::string error;
  if (controller->GetLocalProcessId() == 0)
  {
    try
    {
      result = session::TopologySource(whole, o).at(0);
    }
    catch (const std::exception& e)
    {
      error = e.what();
    }
  }
  error = agreedError(controller, error);
  if (!error.empty())
  {
    throw FieldError(error);
  }
  return broadcastFromRoot(controller, result);
}

const gl::Texture2D& MapperTopology::wholeDepth(const methods::FlowMethod& method, methods::ProcessGroup* group)
{
  // Each process's surface depth is its own piece's; the layer hides what the whole surface
  // hides, so it reads their minimum (the same texture on every process; collective).
  const gl::Texture2D& own = method.surfaceDepth();
  if (!group)
  {
    return own;
  }
  const int w = own.width(), h = own.height();
  if (!wholeDepth_ || wholeDepth_.width() != w || wholeDepth_.height() != h)
  {
    wholeDepth_ = gl::Texture2D(GL_R32F, w, h, GL_NEAREST);
  }
  depthValues_.resize(size_t(w) * size_t(h));
  glGetTextureImage(own.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depthValues_.size() * sizeof(float)),
    depthValues_.data());
  group->minInPlace(depthValues_);
  glTextureSubImage2D(wholeDepth_.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, depthValues_.data());
  return wholeDepth_;
}

void MapperTopology::render(
  const methods::FlowMethod& method, const core::Camera& camera, int w, int h, methods::ProcessGroup* group)
{
  if (!shown_)
  {
    return;
  }
  const gl::Texture2D& depth = wholeDepth(method, group);
  parallel_ = group != nullptr;
  if (!layer_)
  {
    layer_ = std::make_unique<methods::SkeletonLayer>();
  }
  if (!uploaded_)
  {
    layer_->upload(*shown_);
    uploaded_ = true;
  }
  if (!overBlack_ || overBlack_.width() != w || overBlack_.height() != h)
  {
    overBlack_ = gl::Texture2D(GL_RGBA8, w, h, GL_NEAREST);
    overWhite_ = gl::Texture2D(GL_RGBA8, w, h, GL_NEAREST);
  }
  const float black[4] = { 0, 0, 0, 0 }, white[4] = { 1, 1, 1, 0 };
  glClearTexImage(overBlack_.id(), 0, GL_RGBA, GL_FLOAT, black);
  glClearTexImage(overWhite_.id(), 0, GL_RGBA, GL_FLOAT, white);
  layer_->draw(overBlack_, depth, camera, style_);
  layer_->draw(overWhite_, depth, camera, style_);
}

void MapperTopology::composite(
  const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::FlowMethod& method)
{
  if (!shown_ || !overBlack_)
  {
    return;
  }
  if (emptyVao_.id() == 0)
  {
    emptyVao_ = gl::VertexArray::create();
  }
  if (!program_)
  {
    program_ = methods::program(
      { { GL_VERTEX_SHADER, "gpu/fullscreen.vert" }, { GL_FRAGMENT_SHADER, "paraview/topology_overlay.frag" } });
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, guard.drawFramebuffer());
  glViewport(x0, y0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // premultiplied over
  program_.use();
  glUniform2i(program_.uniform("uOrigin"), x0, y0);
  glUniform1f(program_.uniform("uDepthBias"), 2e-5f);
  glBindTextureUnit(methods::bindings::kCompositeColor, overBlack_.id());
  glBindTextureUnit(methods::bindings::kCompositeShade, overWhite_.id());
  glBindTextureUnit(methods::bindings::kCompositeDepth, method.surfaceDepth().id());
  glBindVertexArray(emptyVao_.id());
  const GLint part = program_.uniform("uPart");
  if (!parallel_)
  {
    glUniform1i(part, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  else
  {
    glUniform1i(part, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // The layer over the background, for IceT's composite to keep: its depth, and its
    // coverage as alpha (IceT blends ParaView's background under the processes' image
    // there, as the one-process framebuffer has it under the layer).
    glDepthMask(GL_TRUE);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUniform1i(part, 2);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_FALSE);
  }
  glDisable(GL_BLEND);
}

void MapperTopology::release()
{
  layer_.reset();
  uploaded_ = false;
  overBlack_ = {};
  overWhite_ = {};
  wholeDepth_ = {};
  program_ = {};
  emptyVao_ = {};
}

}  // namespace flowsurf::paraview
