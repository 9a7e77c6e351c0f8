#include "mapper_topology.h"

#include "core/errors.h"
#include "gpu/gpu_bindings.h"
#include "gpu/shader_interface.h"

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
    source_.reset();
    key_.clear();
    return;
  }
  if (parallel)
  {
    throw ConfigError("FlowSurf: FlowSurfTopology is not available under MPI (pvbatch or pvserver on several "
                      "processes) yet: apply the FlowSurf Topology filter to the surface and show its output");
  }
  const std::string key = optionsKey(o);
  if (!dataChanged && key == key_)
  {
    return;
  }
  key_ = key;
  source_.reset();
  uploaded_ = false;
  style_.points = o.topologyParts != "lines";
  style_.lines = o.topologyParts != "points";
  style_.glyphSize = o.topologyGlyphSize;
  style_.lineWidth = o.topologyLineWidth;
  auto source = std::make_unique<session::TopologySource>(steps, o);
  source->at(0);  // analysed now: its error is this render's, once
  source_ = std::move(source);
}

void MapperTopology::render(const methods::FlowMethod& method, const core::Camera& camera, int w, int h)
{
  if (!source_)
  {
    return;
  }
  if (!layer_)
  {
    layer_ = std::make_unique<methods::SkeletonLayer>();
  }
  if (!uploaded_)
  {
    layer_->upload(source_->at(0));
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
  layer_->draw(overBlack_, method.surfaceDepth(), camera, style_);
  layer_->draw(overWhite_, method.surfaceDepth(), camera, style_);
}

void MapperTopology::composite(
  const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::FlowMethod& method)
{
  if (!source_ || !overBlack_)
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
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
}

void MapperTopology::release()
{
  layer_.reset();
  uploaded_ = false;
  overBlack_ = {};
  overWhite_ = {};
  program_ = {};
  emptyVao_ = {};
}

}  // namespace flowsurf::paraview
