// flowsurf — a vtkCompositePolyDataMapper2 that runs a flowsurf method in ParaView's
// OpenGL context and composites the result into ParaView's framebuffer by depth. The
// surface is rasterised once per frame, by the method, where the composite can reproduce
// ParaView's colouring of it (host_look.h); otherwise ParaView draws the surface with its
// own colour mapping first. The composite:
//   blend overlay: ParaView's colour x (beta F_a + (1 - beta)), [L eq. 10] with F_s =
//   ParaView's colouring; gray, gray-lit, hue-lit, coolwarm: the method's image [W Fig. 6].
// VTK's cached GL state is saved around the passes and restored after them.
// The frames run through session::Playback, the command line's frame loop: ISA/IBFVS
// advance one frame per render when the view time or the camera changed, and run the
// warm-up (FlowSurfWarmup, the table's --warmup: 3 / alpha frames by default, none for the
// hybrid) when the method, options, data or view size are new.
#ifndef vtkFlowSurfMapper_h
#define vtkFlowSurfMapper_h

#include "vtkCompositePolyDataMapper2.h"

#include <memory>
#include <string>

class vtkFlowSurfMapper : public vtkCompositePolyDataMapper2
{
public:
  static vtkFlowSurfMapper* New();
  vtkTypeMacro(vtkFlowSurfMapper, vtkCompositePolyDataMapper2);

  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

  void SetVectorsName(const std::string& name);
  // Sets an option of the table by name; returns the error message, empty if none.
  std::string SetOption(const std::string& name, const std::string& value);
  void SetViewTime(double time);
  // The data time of this process's piece as the pipeline delivered it (the representation
  // reads it before ParaView's delivery drops it); none: the data has no time.
  void SetPieceTime(bool has, double time);

protected:
  vtkFlowSurfMapper();
  ~vtkFlowSurfMapper() override;

private:
  vtkFlowSurfMapper(const vtkFlowSurfMapper&) = delete;
  void operator=(const vtkFlowSurfMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
