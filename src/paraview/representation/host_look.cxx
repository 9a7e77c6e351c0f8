#include "host_look.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkSmartPointer.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <limits>

namespace flowsurf::paraview {

namespace {

glm::vec3 rgb(const double c[3])
{
  return glm::vec3(float(c[0]), float(c[1]), float(c[2]));
}

// Above/below-range colours replace the end colours outside the range: not in a table.
bool usesRangeColors(vtkScalarsToColors* lut)
{
  if (auto* ctf = vtkColorTransferFunction::SafeDownCast(lut))
  {
    return ctf->GetUseAboveRangeColor() || ctf->GetUseBelowRangeColor();
  }
  if (auto* lt = vtkLookupTable::SafeDownCast(lut))
  {
    return lt->GetUseAboveRangeColor() || lt->GetUseBelowRangeColor();
  }
  return false;
}

// ParaView keeps a visibility per block; the method draws every block of the input.
bool anyBlockHidden(vtkCompositeDataDisplayAttributes* blocks, vtkDataObject* input)
{
  auto* cd = vtkCompositeDataSet::SafeDownCast(input);
  if (!cd || !blocks->HasBlockVisibilities())
  {
    return false;
  }
  auto it = vtk::TakeSmartPointer(cd->NewIterator());
  it->SkipEmptyNodesOff();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkDataObject* leaf = it->GetCurrentDataObject();
    if (leaf && blocks->HasBlockVisibility(leaf) && !blocks->GetBlockVisibility(leaf))
    {
      return true;
    }
  }
  return false;
}

// The scalar colouring, or false when it cannot be reproduced.
bool scalarLook(vtkCompositePolyDataMapper2* mapper, HostLook& look)
{
  if (mapper->GetScalarMode() != VTK_SCALAR_MODE_USE_POINT_FIELD_DATA || !mapper->GetArrayName() ||
    !*mapper->GetArrayName() || mapper->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS)
  {
    return false;
  }
  vtkScalarsToColors* lut = mapper->GetLookupTable();
  if (!lut || lut->UsingLogScale() || lut->GetIndexedLookup() || usesRangeColors(lut) ||
    lut->GetVectorMode() == vtkScalarsToColors::RGBCOLORS)
  {
    return false;
  }
  ColorSource source;
  source.array = mapper->GetArrayName();
  source.component = lut->GetVectorMode() == vtkScalarsToColors::COMPONENT ? lut->GetVectorComponent() : -1;
  look.scalars = source;
  const double* r = lut->GetRange();
  look.range = glm::vec2(float(r[0]), float(r[1]));
  look.table.resize(256);
  double c[3];
  for (int i = 0; i < 256; ++i)  // entry i at value01 = i / 255, as the overlay samples it
  {
    lut->GetColor(r[0] + (r[1] - r[0]) * i / 255.0, c);
    look.table[size_t(i)] = rgb(c);
  }
  lut->GetColor(std::numeric_limits<double>::quiet_NaN(), c);
  look.nanColor = rgb(c);
  return true;
}

}  // namespace

std::optional<HostLook> hostLook(vtkRenderer* ren, vtkActor* actor, vtkCompositePolyDataMapper2* mapper,
  vtkDataObject* input)
{
  vtkProperty* prop = actor->GetProperty();
  auto* blocks = mapper->GetCompositeDataDisplayAttributes();
  if (!prop || prop->GetOpacity() < 1.0 || actor->GetTexture() || prop->GetNumberOfTextures() > 0 ||
    prop->GetRepresentation() != VTK_SURFACE || prop->GetEdgeVisibility() || prop->GetSpecular() > 0.0 ||
    (blocks && (blocks->HasBlockColors() || blocks->HasBlockOpacities() || anyBlockHidden(blocks, input))))
  {
    return std::nullopt;
  }
  HostLook look;
  look.solid = rgb(prop->GetDiffuseColor());
  if (mapper->GetScalarVisibility() && !scalarLook(mapper, look))
  {
    return std::nullopt;
  }
  look.lighting = prop->GetLighting();
  look.ambient = float(prop->GetAmbient());
  look.diffuse = float(prop->GetDiffuse());
  // Lights: world-space direction (position to focal point, after the camera transform of
  // camera lights) turned into eye space; positional lights count as directional.
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetViewTransformMatrix();
  vtkLightCollection* lights = ren->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    if (int(look.lightDirEye.size()) == kMaxHostLights)
    {
      return std::nullopt;
    }
    double p[3], f[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    double d[4] = { f[0] - p[0], f[1] - p[1], f[2] - p[2], 0.0 }, e[4];
    view->MultiplyPoint(d, e);
    const glm::vec3 dir{ float(e[0]), float(e[1]), float(e[2]) };
    if (glm::length(dir) == 0.0f)
    {
      continue;
    }
    look.lightDirEye.push_back(glm::normalize(dir));
    look.lightColor.push_back(rgb(light->GetDiffuseColor()) * float(light->GetIntensity()));
  }
  return look;
}

session::RenderOptions frameLoopOptions(
  const session::RenderOptions& options, bool dataColor, const std::string& vectors, const core::Viewport& size)
{
  session::RenderOptions o = options;
  methods::CommonParams& p = o.params.common;
  if (p.overlay == methods::OverlayScheme::Blend)
  {
    p.colormap = methods::Colormap::None;
    p.lighting = false;
  }
  if (dataColor)
  {
    p.colorBy = kColorScalarName;
    p.colorRange = { 1.0f, 0.0f };
    p.colorRangeAuto = false;
    p.colorRangeMode = methods::RangeMode::Data;  // ParaView's table maps the data's range
    p.colorScale = methods::ColorScale::Linear;    // linearly (its own log scale aside)
  }
  o.field = vectors;
  o.size = size;
  o.topology = false;  // drawn by the mapper over ParaView's colours (mapper_topology.h)
  return o;
}

}  // namespace flowsurf::paraview
