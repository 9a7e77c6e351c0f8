// flowsurf — FlowSurfTopology on: the flow topology of the surface drawn over the FlowSurf
// representation (docs/topology.md §5), analysed once per data or option change
// (session::TopologySource over the mapper's piece) and drawn by methods::SkeletonLayer as
// every front end draws it, but onto two textures of its own, cleared black and white (the
// layer keeps its target's alpha: the difference of the two is its coverage), then blended
// over ParaView's framebuffer after the method's composite. So ParaView's colouring, which
// the blend overlay multiplies into the texture, never tints the lines and glyphs.
// Serial ParaView only: under MPI a process's piece is not the whole surface (the FlowSurf
// Topology filter gathers it); refused there with a ConfigError.
#ifndef mapper_topology_h
#define mapper_topology_h

#include "gl_state_guard.h"

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/frame.h"
#include "methods/skeleton_layer/skeleton_layer.h"
#include "session/options/options.h"
#include "session/topology_source.h"

#include <memory>
#include <string>

namespace flowsurf::paraview {

class MapperTopology
{
public:
  // Re-analyses `steps` when `dataChanged` or the options `o` (the frame loop's) changed.
  // Throws the analysis's error once (later renders of the same input draw nothing), and
  // ConfigError when FlowSurfTopology is on under MPI (`parallel`).
  void update(core::StepProvider& steps, const session::RenderOptions& o, bool dataChanged, bool parallel);
  // Draws the layer into its textures (w x h, the method's size); then composite() blends
  // them into the guard's draw framebuffer at (x0, y0). Needs the method's last frame.
  void render(const methods::FlowMethod& method, const core::Camera& camera, int w, int h);
  void composite(const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::FlowMethod& method);
  bool active() const { return source_ != nullptr; }
  void release();

private:
  std::unique_ptr<session::TopologySource> source_;  // null: FlowSurfTopology off, or failed
  std::string key_;                                  // the options source_ was made for
  bool uploaded_ = false;
  methods::SkeletonStyle style_;
  std::unique_ptr<methods::SkeletonLayer> layer_;
  gl::Texture2D overBlack_, overWhite_;
  gl::Program program_;
  gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::paraview

#endif
