// flowsurf — the FlowSurf mapper's last pass: the method's image composited into
// ParaView's framebuffer by depth, over the rectangle this process's piece can cover (in
// parallel each process draws its own fragments; IceT composites the processes).
//   blend overlay: ParaView's colour x (beta F_a + (1 - beta)), [L eq. 10] with F_s =
//   ParaView's colouring; otherwise the method's image. With ParaView's look reproduced
//   (host_look.h) the surface's colour comes from the method's shade and ParaView's
//   lookup table (one surface pass per frame).
// Cost: one full-screen triangle, scissored to the piece's rectangle.
#ifndef mapper_composite_h
#define mapper_composite_h

#include "gl_state_guard.h"
#include "host_look.h"

#include "gl/objects.h"
#include "methods/frame.h"
#include "parallel/screen_split.h"

#include <glm/glm.hpp>

#include <vector>

namespace flowsurf::paraview {

class MapperComposite
{
public:
  // Draws `method`'s composite into the guard's draw framebuffer at (x0, y0), w x h, where
  // `piece` (pixels of the view) allows. `host`: ParaView's look to reproduce (null: its
  // own pass drew the surface); `valueRange`: the colour value's range the shade encodes.
  void draw(const GlStateGuard& guard, int x0, int y0, int w, int h, const methods::PixelRect& piece,
    const methods::FlowMethod& method, const HostLook* host, bool blend, glm::vec2 valueRange);
  void release();

private:
  void setHostLook(const gl::Program& program, const HostLook& look, bool blend, glm::vec2 valueRange);

  gl::Program composite_, compositeHost_;
  gl::VertexArray emptyVao_;
  gl::Texture2D hostTable_;                // the lookup table's 256 colours, RGBA8
  std::vector<glm::vec3> hostTableColors_; // what hostTable_ holds: uploaded when it changes
};

}  // namespace flowsurf::paraview

#endif
