#include "vtkFlowSurfTopologyFilter.h"

#include "polydata_to_mesh.h"
#include "io/skeleton_polydata.h"
#include "surface_gather.h"

#include "core/errors.h"
#include "session/options/options.h"
#include "session/topology_source.h"
#include "skeleton/skeleton.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <exception>
#include <string>

namespace {

using flowsurf::core::SurfaceMesh;

// A data set's surface: itself when it is polydata, else its surface (ParaView's Extract
// Surface: 2D cells as they are, a volume's boundary faces).
vtkSmartPointer<vtkPolyData> surfaceOf(vtkDataSet* data)
{
  if (auto* pd = vtkPolyData::SafeDownCast(data))
  {
    return pd;
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  surface->Update();
  return surface->GetOutput();
}

void append(SurfaceMesh& into, const SurfaceMesh& piece)
{
  const auto base = uint32_t(into.positions.size());
  if (into.fields.empty())
  {
    into.fields = { { piece.fields.empty() ? std::string() : piece.fields[0].name, {} } };
  }
  into.positions.insert(into.positions.end(), piece.positions.begin(), piece.positions.end());
  if (!piece.fields.empty())
  {
    auto& v = into.fields[0].values;
    v.insert(v.end(), piece.fields[0].values.begin(), piece.fields[0].values.end());
  }
  for (const glm::uvec3& t : piece.triangles)
  {
    into.triangles.push_back(t + glm::uvec3(base));
  }
}

// This process's piece as positions, triangles and the field (FieldError when a surface
// with triangles lacks the array).
SurfaceMesh pieceMesh(vtkDataObject* input, const std::string& field)
{
  SurfaceMesh mesh;
  auto leaf = [&](vtkDataSet* ds) {
    if (!ds)
    {
      return;
    }
    vtkSmartPointer<vtkPolyData> surface = surfaceOf(ds);
    vtkDataArray* v = surface->GetPointData()->GetArray(field.c_str());
    if ((surface->GetNumberOfPolys() > 0 || surface->GetNumberOfStrips() > 0) &&
      (!v || v->GetNumberOfComponents() != 3))
    {
      throw flowsurf::FieldError("FlowSurf Topology: the surface has no 3-component point array '" + field +
        "' (Vectors): pick one of its point vector arrays");
    }
    append(mesh, flowsurf::paraview::toSurfaceMesh(surface, field));
  };
  if (auto* cd = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto it = vtk::TakeSmartPointer(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      leaf(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
    }
  }
  else
  {
    leaf(vtkDataSet::SafeDownCast(input));
  }
  return mesh;
}

}  // namespace

class vtkFlowSurfTopologyFilter::vtkInternals
{
public:
  flowsurf::session::RenderOptions Options;
};

vtkStandardNewMacro(vtkFlowSurfTopologyFilter);

vtkFlowSurfTopologyFilter::vtkFlowSurfTopologyFilter()
  : Internals(new vtkInternals)
{
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
}

vtkFlowSurfTopologyFilter::~vtkFlowSurfTopologyFilter()
{
  delete this->Internals;
}

void vtkFlowSurfTopologyFilter::SetFlowSurfOptionText(const char* option, const char* value)
{
  try
  {
    flowsurf::session::setOption(this->Internals->Options, option ? option : "", value ? value : "");
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
  }
  this->Modified();
}

void vtkFlowSurfTopologyFilter::SetFlowSurfOptionInt(const char* option, int value)
{
  this->SetFlowSurfOptionText(option, std::to_string(value).c_str());
}

void vtkFlowSurfTopologyFilter::SetFlowSurfOptionDouble(const char* option, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  this->SetFlowSurfOptionText(option, text);
}

int vtkFlowSurfTopologyFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkFlowSurfTopologyFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace flowsurf;
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool root = !controller || controller->GetLocalProcessId() == 0;

  // (1) this process's piece; one process's error is every process's (no one waits alone
  // in the gather).
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  const char* name = arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME())
    ? arrayInfo->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  const std::string field = name ? name : "";
  SurfaceMesh piece;
  std::string error;
  try
  {
    if (field.empty())
    {
      throw FieldError("FlowSurf Topology: no point vector array selected (Vectors): the input needs a "
                       "3-component point array");
    }
    piece = pieceMesh(input, field);
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  error = paraview::agreedError(controller, error);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  // (2) the whole surface on process 0, analysed there as one process would: the field as
  // the options show it (--reverse-field), welded at the pieces' shared vertices.
  SurfaceMesh whole = paraview::gatherToRoot(controller, piece);
  skeleton::Skeleton result;
  if (root)
  {
    try
    {
      std::vector<glm::vec3> shown = whole.fields.empty() ? std::vector<glm::vec3>() : whole.fields[0].values;
      if (session::fieldShownReversed(this->Internals->Options, field))
      {
        for (glm::vec3& v : shown)
        {
          v = -v;
        }
      }
      result = skeleton::analyze(
        whole, shown, session::topologyParams(this->Internals->Options), "FlowSurf Topology, field '" + field + "'");
    }
    catch (const std::exception& e)
    {
      error = e.what();
    }
  }
  error = paraview::agreedError(controller, error);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (root)
  {
    output->ShallowCopy(io::skeletonPolyData(result));
  }
  return 1;
}

void vtkFlowSurfTopologyFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
