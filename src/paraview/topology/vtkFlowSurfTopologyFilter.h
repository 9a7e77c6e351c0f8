// flowsurf — the "FlowSurf Topology" filter: the flow topology (docs/topology.md) of a point
// vector array on any surface, as polydata that ParaView's own representations style: the
// critical points as vertices (type, type_name, index), the separation and attachment lines
// as polylines (kind, kind_name, strength), in the input's coordinates. Its properties
// (FlowSurfTopology.xml) are generated from the option table; each calls one of the
// SetFlowSurfOption* setters with the option's name. Under MPI the pieces are gathered and
// analysed as one surface on process 0, which outputs the whole result (the others: empty).
#ifndef vtkFlowSurfTopologyFilter_h
#define vtkFlowSurfTopologyFilter_h

#include "FlowSurfTopologyModule.h"  // for export macro
#include "vtkPolyDataAlgorithm.h"

class FLOWSURFTOPOLOGY_EXPORT vtkFlowSurfTopologyFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkFlowSurfTopologyFilter* New();
  vtkTypeMacro(vtkFlowSurfTopologyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // One option of src/session/options by its command-line name ("topology-scale").
  void SetFlowSurfOptionText(const char* option, const char* value);
  void SetFlowSurfOptionInt(const char* option, int value);
  void SetFlowSurfOptionDouble(const char* option, double value);

protected:
  vtkFlowSurfTopologyFilter();
  ~vtkFlowSurfTopologyFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkFlowSurfTopologyFilter(const vtkFlowSurfTopologyFilter&) = delete;
  void operator=(const vtkFlowSurfTopologyFilter&) = delete;

  // The options the properties set (a session::RenderOptions).
  class vtkInternals;
  vtkInternals* Internals;
};

#endif
