// flowsurf — FlowSurfTopology on: the flow topology of the surface drawn over the FlowSurf
// representation (docs/topology.md §5), analysed once per data or option change
// (session::TopologySource over the whole surface) and drawn by methods::SkeletonLayer as
// every front end draws it, but onto two textures of its own, cleared black and white (the
// layer keeps its target's alpha: the difference of the two is its coverage), then blended
// over ParaView's framebuffer after the method's composite. So ParaView's colouring, which
// the blend overlay multiplies into the texture, never tints the lines and glyphs.
// Under MPI a process's piece is not the whole surface: the pieces are gathered on process 0
// and analysed there once (surface_gather.h, as the FlowSurf Topology filter does), the
// result sent to every process. Each process draws all of it, hidden where the whole
// surface's depth (the processes' minimum) lies in front, over its own fragments; IceT's
// depth composite then keeps, at each pixel, the process whose surface is nearest, whose
// layer there is the one-process layer; over the background every process draws the same
// layer, written with a depth short of the far plane (IceT drops far-plane pixels).
#ifndef mapper_topology_h
#define mapper_topology_h

#include "gl_state_guard.h"

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/frame.h"
#include "methods/skeleton_layer/skeleton_layer.h"
#include "parallel/process_group.h"
#include "session/options/options.h"
#include "session/topology_source.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace flowsurf::paraview {

class MapperTopology
{
public:
  // Re-analyses `steps` when `dataChanged` or the options `o` (the frame loop's) changed;
  // `parallel` (collective then, on every process with the same options): `steps` is this
  // process's piece of the surface analysed. Throws the analysis's error once (later renders
  // of the same input draw nothing), the same on every process.
  void update(core::StepProvider& steps, const session::RenderOptions& o, bool dataChanged, bool parallel);
  // Draws the layer into its textures (w x h, the method's size); then composite() blends
  // them into the guard's draw framebuffer at (x0, y0). Needs the method's last frame.
  // `group`: the processes rendering together (collective then), null in serial.
  void render(const methods::FlowMethod& method, const core::Camera& camera, int w, int h, methods::ProcessGroup* group);
  void composite(const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::FlowMethod& method);
  bool active() const { return shown_.has_value(); }
  void release();

private:
  static skeleton::Skeleton analyzeWhole(core::StepProvider& steps, const session::RenderOptions& o);
  const gl::Texture2D& wholeDepth(const methods::FlowMethod& method, methods::ProcessGroup* group);

  std::optional<skeleton::Skeleton> shown_;  // empty: FlowSurfTopology off, or failed
  std::string key_;                                  // the options shown_ was made for
  bool uploaded_ = false;
  bool parallel_ = false;  // the last render's: drawn for IceT's composite (composite())
  methods::SkeletonStyle style_;
  std::unique_ptr<methods::SkeletonLayer> layer_;
  gl::Texture2D overBlack_, overWhite_;
  gl::Texture2D wholeDepth_;        // R32F: the processes' minimum surface depth (parallel)
  std::vector<float> depthValues_;
  gl::Program program_;
  gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::paraview

#endif
