// Index: Internals (state) · options · render: (0) ParaView's surface pass, unless its look
// is reproduced (host_look.h) (1) surface (updateSurface) (2) the frame loop
// (session::Playback, updatePlayback) (3) advection frames (4) composite into ParaView's
// framebuffer (mapper_composite.h).
#include "vtkFlowSurfMapper.h"

#include "gl_state_guard.h"
#include "host_look.h"
#include "mapper_composite.h"
#include "mapper_topology.h"
#include "polydata_to_mesh.h"
#include "rank_stats.h"
#include "vtk_process_group.h"

#include "core/errors.h"
#include "gl/objects.h"
#include "parallel/agreeing_group.h"
#include "parallel/process_group.h"
#include "raster/surface_gpu.h"
#include "session/options/options.h"
#include "session/playback.h"

#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"

#include <epoxy/gl.h>

#include <optional>
#include <string>
#include <vector>

namespace fs = flowsurf;

using flowsurf::paraview::cameraOf;
using flowsurf::paraview::PieceSteps;

struct vtkFlowSurfMapper::Internals
{
  fs::session::RenderOptions options;
  std::string vectors;
  double viewTime = 0.0;
  std::optional<double> pieceTime;  // the data time of this piece (SetPieceTime)

  vtkMTimeType dataTime = 0;
  std::string dataVectors;
  std::optional<fs::paraview::ColorSource> dataColor;  // the colour array carried by the steps
  bool haveMesh = false;
  PieceSteps steps;
  std::unique_ptr<fs::session::Playback> playback;  // the frame loop of every front end
  std::optional<double> lastTime;
  fs::core::Camera lastCamera;

  // The processes rendering this view together (pvbatch / pvserver under mpiexec); null
  // when ParaView runs on one. Every decision below that leads to a collective step is
  // made the same on all processes (VtkProcessGroup::any).
  std::unique_ptr<fs::paraview::VtkProcessGroup> group;
  // The same processes for the frame loop: an error on one inside a collective section
  // (inSection) becomes the same error on all, none left waiting (agreeing_group.h).
  std::unique_ptr<fs::methods::AgreeingGroup> frameGroup;
  bool groupChecked = false;
  template <class Section>
  void inSection(Section&& section)
  {
    fs::methods::collectiveSection(frameGroup.get(), section);
  }

  fs::paraview::MapperComposite composite;
  fs::paraview::MapperTopology topology;  // FlowSurfTopology on (serial ParaView)
  bool glChecked = false;

  // ParaView's look of the surface when the composite reproduces it (one surface pass per
  // frame); nullopt: ParaView's own pass drew the surface first. Set by Render.
  std::optional<fs::paraview::HostLook> host;
  bool pathLogged = false;
  std::unique_ptr<fs::paraview::RankStats> stats = fs::paraview::RankStats::fromEnvironment();

  void releaseGl()
  {
    playback.reset();
    composite.release();
    topology.release();
  }

  fs::session::RenderOptions playbackOptions(const fs::core::Viewport& size) const
  {
    return fs::paraview::frameLoopOptions(options, dataColor.has_value(), vectors, size);
  }

  void render(vtkRenderer* ren, vtkDataObject* input, vtkOpenGLRenderWindow* win);
  void checkGl();  // OpenGL 4.5 on every process (once)
  // (1) The piece converted when the data, the array or the colour array changed (on any
  // process); true then. Throws the group's first error.
  bool updateSurface(vtkDataObject* input);
  // (2) The frame loop for `size` (new, rebuilt or updated); true when it needs its warm-up.
  bool updatePlayback(const fs::core::Viewport& size, bool dataChanged, bool timeChanged);
};

vtkStandardNewMacro(vtkFlowSurfMapper);

vtkFlowSurfMapper::vtkFlowSurfMapper()
  : Impl(new Internals)
{
}

vtkFlowSurfMapper::~vtkFlowSurfMapper() = default;

void vtkFlowSurfMapper::SetVectorsName(const std::string& name)
{
  if (name != this->Impl->vectors)
  {
    this->Impl->vectors = name;
    this->Modified();
  }
}

std::string vtkFlowSurfMapper::SetOption(const std::string& name, const std::string& value)
{
  try
  {
    if (fs::session::findOption(name)->get(this->Impl->options) == value)
    {
      return {};
    }
    fs::session::setOption(this->Impl->options, name, value);
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  this->Modified();
  return {};
}

void vtkFlowSurfMapper::SetViewTime(double time)
{
  this->Impl->viewTime = time;
}

void vtkFlowSurfMapper::SetPieceTime(bool has, double time)
{
  this->Impl->pieceTime = has ? std::optional<double>(time) : std::nullopt;
}

void vtkFlowSurfMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Impl->releaseGl();
  this->Impl->glChecked = false;
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkFlowSurfMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  if (ren->GetSelector() || !win)
  {
    this->Superclass::Render(ren, act);  // picking passes draw ids, not colours
    return;
  }
  // (0) ParaView's surface with its own colour mapping (colour and depth), unless the
  // composite reproduces that look from the method's own surface pass. In parallel every
  // process must take the same road (the decision feeds collective steps).
  std::optional<fs::paraview::HostLook> look = fs::paraview::hostLook(ren, act, this, input);
  Internals& impl = *this->Impl;
  if (!impl.groupChecked)
  {
    impl.group = fs::paraview::parallelGroup();
    if (impl.group)
    {
      impl.frameGroup = std::make_unique<fs::methods::AgreeingGroup>(*impl.group);
    }
    impl.groupChecked = true;
  }
  if (impl.group && impl.group->any(!look))
  {
    look.reset();
  }
  if (look.has_value() != impl.host.has_value() || !impl.pathLogged)
  {
    vtkLogF(1, "FlowSurf: %s", look ? "one surface pass (ParaView's look reproduced)"
                                    : "ParaView's surface pass, then the method's");
    impl.pathLogged = true;
  }
  impl.host = look;
  if (!look)
  {
    this->Superclass::Render(ren, act);
  }
  try
  {
    impl.render(ren, input, win);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    while (glGetError() != GL_NO_ERROR)  // e.g. a failed allocation's: not for ParaView to find
    {
    }
    if (look)
    {
      this->Superclass::Render(ren, act);  // the surface at least, in ParaView's colours
    }
  }
}


void vtkFlowSurfMapper::Internals::checkGl()
{
  if (glChecked)
  {
    return;
  }
  inSection([] {
    if (epoxy_gl_version() < 45)
    {
      throw fs::GlError("FlowSurf needs OpenGL 4.5; ParaView's context is " +
        std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))));
    }
  });
  glChecked = true;
}

bool vtkFlowSurfMapper::Internals::updateSurface(vtkDataObject* input)
{
  std::optional<fs::paraview::ColorSource> color;
  if (host && host->scalars)
  {
    color = host->scalars;
  }
  const bool colorChanged = color.has_value() != dataColor.has_value() ||
    (color && (color->array != dataColor->array || color->component != dataColor->component));
  bool dataChanged = input ? (input->GetMTime() != dataTime || vectors != dataVectors || colorChanged) : haveMesh;
  if (group)
  {
    dataChanged = group->any(dataChanged);
  }
  if (!dataChanged)
  {
    return false;
  }
  std::string error;
  fs::core::SurfaceMesh mesh;
  try
  {
    inSection([&] {
      mesh = input ? fs::paraview::toSurfaceMesh(input, vectors, color ? &*color : nullptr) : fs::core::SurfaceMesh{};
      if (mesh.fields.empty())
      {
        mesh.fields.push_back({ vectors, {} });  // an empty piece
      }
      if (color && mesh.scalars.empty())
      {
        mesh.scalars.push_back({ fs::paraview::kColorScalarName, {} });
      }
      if (mesh.triangleCount() > 0)
      {
        fs::core::validateMesh(mesh, "FlowSurf input");
      }
    });
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  if (group && error.empty())  // the same on every process: a collective step for all
  {
    error = group->sameValue(input && pieceTime, pieceTime.value_or(0.0), "the pieces' data times");
  }
  if (!error.empty())
  {
    playback.reset();
    haveMesh = false;
    throw fs::FieldError(error);
  }
  steps.mesh = std::move(mesh);
  haveMesh = input != nullptr;
  dataTime = input ? input->GetMTime() : 0;
  dataVectors = vectors;
  dataColor = color;
  return true;
}

bool vtkFlowSurfMapper::Internals::updatePlayback(const fs::core::Viewport& size, bool dataChanged, bool timeChanged)
{
  const fs::session::RenderOptions o = playbackOptions(size);
  bool warmup = false;
  std::string error;
  try
  {
    inSection([&] {  // a shader that failed on one process fails them all
      if (playback && dataChanged && timeChanged && playback->options().field == o.field)
      {
        playback->stepsChanged();  // the texture goes on over the new time step
        warmup = playback->setOptions(o) >= fs::session::OptionEffect::Rebuild;  // rebuilt by warmUp()
      }
      else if (!playback || dataChanged)
      {
        playback.reset();
        // Kept only once open: a playback that failed to open is not kept.
        auto opened =
          std::make_unique<fs::session::Playback>(o, std::vector<fs::methods::Method>{}, frameGroup.get());
        opened->open(steps);
        playback = std::move(opened);
        warmup = true;
      }
      else
      {
        warmup = playback->setOptions(o) >= fs::session::OptionEffect::Rebuild;
      }
    });
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  if (!error.empty())
  {
    playback.reset();
    throw fs::Error(error);
  }
  return warmup;
}

void vtkFlowSurfMapper::Internals::render(vtkRenderer* ren, vtkDataObject* input, vtkOpenGLRenderWindow* win)
{
  // Every step that can fail on one process alone is followed by an agreement, so that all
  // report the same error and none is left waiting in a collective step (inSection).
  checkGl();
  if (!input && !group)
  {
    return;  // in parallel an empty piece still takes part
  }
  int w = 0, h = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  if (w < 1 || h < 1)
  {
    return;
  }
  const fs::core::Camera camera = cameraOf(ren->GetActiveCamera());

  fs::paraview::GlStateGuard guard(win->GetState());

  // (1) the surface, converted when the data, the array or the colour array change; in
  // parallel each process holds a piece and scales by the whole surface's statistics
  const bool dataChanged = updateSurface(input);
  if (steps.mesh.triangleCount() == 0 && !group)
  {
    return;
  }

  // (2) the frame loop: new renderers when options, the colour array or the view size
  // change (the table's effects), a new upload when only the data changed at a new view time
  // (decided for the group: each frame is collective)
  bool timeChanged = lastTime && *lastTime != viewTime;
  bool cameraChanged = !fs::core::sameCamera(camera, lastCamera);
  if (group)
  {
    timeChanged = group->any(timeChanged);
    cameraChanged = group->any(cameraChanged);
  }
  const bool warmup = updatePlayback({ w, h }, dataChanged, timeChanged);
  {
    fs::session::RenderOptions o = playbackOptions({ w, h });
    o.topology = options.topology;  // the frame loop's options without it: drawn here
    topology.update(steps, o, dataChanged, group != nullptr);
  }

  // (3) advection frames: a still render of something new converges (the warm-up, then
  // frame 0); a new view time or camera advances one frame (with the camera-move remedy);
  // otherwise the last image. The clock is the command line's (session/playback.h).
  const bool frames = warmup || timeChanged || cameraChanged;
  if (stats && frames)
  {
    stats->begin(*playback, group.get());
  }
  inSection([&] {  // an error on one process inside a frame stops the frame on all
    if (warmup)
    {
      playback->warmUp({ camera });
      playback->render({ camera });
    }
    else if (timeChanged || cameraChanged)
    {
      playback->render({ camera });
    }
  });
  if (stats && frames)
  {
    stats->end(*playback, group.get(), warmup);
  }
  lastTime = viewTime;
  lastCamera = camera;

  // (4) composite into ParaView's framebuffer by depth, only where this piece can be
  const fs::methods::SurfaceGpu* drawn = playback->surface().current();
  const fs::methods::PixelRect piece = drawn
    ? fs::methods::projectedRect(drawn->pieceParts(), lastCamera.viewProjection(float(w) / float(h)), w, h)
    : fs::methods::PixelRect{};
  topology.render(*playback->views()[0], lastCamera, w, h, group.get());
  composite.draw(guard, x0, y0, w, h, piece, *playback->views()[0], host ? &*host : nullptr,
    options.params.common.overlay == fs::methods::OverlayScheme::Blend, playback->surface().colorRange());
  // (5) the flow topology over it (FlowSurfTopology on)
  topology.composite(guard, x0, y0, w, h, *playback->views()[0]);
}
