// flowsurf — the "FlowSurf Skin Friction" filter: the wall shear stress derived from the
// velocity next to the walls (docs/cfd.md, `--field skin-friction`) on what ParaView's own
// readers give. Input: a composite data set with a volume block (OpenFOAM's "internalMesh",
// else the first block with volume cells) and the wall patches as polydata blocks (every
// patch read is taken as a wall: pick them in the reader's Mesh Regions), or one volume data
// set, whose boundary surface is the wall. Output: the walls, each with the cell array
// "skin-friction" (kinematic m2/s2 with a viscosity, else the relative gradient 1/s).
#ifndef vtkFlowSurfSkinFrictionFilter_h
#define vtkFlowSurfSkinFrictionFilter_h

#include "FlowSurfSkinFrictionModule.h"  // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

class FLOWSURFSKINFRICTION_EXPORT vtkFlowSurfSkinFrictionFilter : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkFlowSurfSkinFrictionFilter* New();
  vtkTypeMacro(vtkFlowSurfSkinFrictionFilter, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Kinematic viscosity in m^2/s; 0: the direction and a relative magnitude.
  vtkSetClampMacro(Viscosity, double, 0.0, 1e30);
  vtkGetMacro(Viscosity, double);

protected:
  vtkFlowSurfSkinFrictionFilter() = default;
  ~vtkFlowSurfSkinFrictionFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkFlowSurfSkinFrictionFilter(const vtkFlowSurfSkinFrictionFilter&) = delete;
  void operator=(const vtkFlowSurfSkinFrictionFilter&) = delete;

  double Viscosity = 0.0;
};

#endif
