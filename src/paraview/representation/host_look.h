// flowsurf — how ParaView would draw the surface (its colour mapping, material and lights),
// reproduced in the plugin's composite so that ParaView's own surface pass can be skipped:
// the method's G-buffer pass is then the only rasterisation of the surface per frame.
// Reproduced: a solid colour, or a point array mapped through a linear lookup table
// (magnitude or one component), NaN colour, ambient + diffuse shading under the renderer's
// directional lights (two-sided). Not reproduced (ParaView draws the surface first, as
// before): translucency, textures, cell scalars, direct RGB scalars, log-scale or indexed
// lookup tables, above/below-range colours, specular highlights, edges, per-block colours.
#ifndef host_look_h
#define host_look_h

#include "polydata_to_mesh.h"

#include "session/options/options.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

class vtkActor;
class vtkCompositePolyDataMapper2;
class vtkDataObject;
class vtkRenderer;

namespace flowsurf::paraview {

struct HostLook
{
  std::optional<ColorSource> scalars;  // none: the solid colour
  std::vector<glm::vec3> table;        // 256 colours over `range` (scalars only)
  glm::vec2 range{ 0.0f, 1.0f };
  glm::vec3 nanColor{ 0.5f };
  glm::vec3 solid{ 1.0f };
  float ambient = 0.0f, diffuse = 1.0f;
  bool lighting = true;
  // Directional lights in eye space: direction the light travels, colour x intensity.
  std::vector<glm::vec3> lightDirEye, lightColor;
};
inline constexpr int kMaxHostLights = 8;

// What `mapper` (ParaView's surface mapper state) would draw for `actor` in `ren`, from the
// mapper's settings alone (the same on every process, also one with an empty piece); nullopt
// when something listed above as not reproduced is in use.
std::optional<HostLook> hostLook(vtkRenderer* ren, vtkActor* actor, vtkCompositePolyDataMapper2* mapper,
  vtkDataObject* input);

// The options the frame loop runs with, from the representation's `options`: with the blend
// overlay F_s is ParaView's colouring, so the method's own colour map and lighting are off
// and its image is beta F_a + (1 - beta); with a colour array (`dataColor`) the colour value
// the composite maps through ParaView's table; the field is ParaView's array `vectors`, the
// size its view's; the flow topology off (the mapper draws it, mapper_topology.h).
session::RenderOptions frameLoopOptions(
  const session::RenderOptions& options, bool dataColor, const std::string& vectors, const core::Viewport& size);

}  // namespace flowsurf::paraview

#endif
