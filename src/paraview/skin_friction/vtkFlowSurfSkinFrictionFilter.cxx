#include "vtkFlowSurfSkinFrictionFilter.h"

#include "core/errors.h"
#include "io/reader/skin_friction.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkFlowSurfSkinFrictionFilter);

void vtkFlowSurfSkinFrictionFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Viscosity: " << this->Viscosity << "\n";
}

int vtkFlowSurfSkinFrictionFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkFlowSurfSkinFrictionFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  namespace io = flowsurf::io::detail;
  io::SkinFrictionOptions options;
  options.viscosity = this->Viscosity;
  options.warn = [this](const std::string& message) { vtkWarningMacro(<< message); };
  try
  {
    if (auto* volume = vtkDataSet::SafeDownCast(input))
    {
      // One volume: its boundary surface is the wall (at rest unless its points carry a velocity).
      output->SetNumberOfBlocks(1);
      output->SetBlock(0, io::newBoundaryWithSkinFriction(volume, options, "FlowSurf Skin Friction"));
      return 1;
    }
    auto* composite = vtkCompositeDataSet::SafeDownCast(input);
    if (!composite)
    {
      vtkErrorMacro(<< "FlowSurf Skin Friction: the input is neither a data set nor a composite one");
      return 0;
    }
    vtkDataSet* volume = nullptr;
    std::vector<vtkSmartPointer<vtkPolyData>> walls;
    std::vector<std::string> names;
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      const std::string name =
        it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME())
        ? it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME())
        : "block " + std::to_string(it->GetCurrentFlatIndex());
      if (!ds)
      {
        continue;
      }
      if (auto* patch = vtkPolyData::SafeDownCast(ds))
      {
        // A copy of its own: the array is added to the output only.
        auto wall = vtkSmartPointer<vtkPolyData>::New();
        wall->ShallowCopy(patch);
        walls.push_back(wall);
        names.push_back(name);
      }
      else if ((name == "internalMesh" || !volume) && io::hasVolumeCells(ds))
      {
        volume = ds;
      }
    }
    if (!volume)
    {
      vtkErrorMacro(<< "FlowSurf Skin Friction: no block with volume cells (an OpenFOAM reader needs "
                       "internalMesh among its Mesh Regions)");
      return 0;
    }
    if (walls.empty())
    {
      // No patches read: the volume's boundary is the wall.
      output->SetNumberOfBlocks(1);
      output->SetBlock(0, io::newBoundaryWithSkinFriction(volume, options, "FlowSurf Skin Friction"));
      return 1;
    }
    // The patches' own velocity is the wall's (a moving wall), their nut the wall functions' ν_t.
    options.velocity = io::findVelocityArray(volume);
    options.wallVelocity = options.velocity;
    options.turbulentViscosity = "nut";
    std::vector<vtkPolyData*> raw;
    std::vector<std::string> labels;
    for (size_t i = 0; i < walls.size(); ++i)
    {
      raw.push_back(walls[i]);
      labels.push_back("block '" + names[i] + "'");
    }
    io::addSkinFriction(volume, raw, labels, options, "FlowSurf Skin Friction");
    output->SetNumberOfBlocks(static_cast<unsigned>(walls.size()));
    for (size_t i = 0; i < walls.size(); ++i)
    {
      output->SetBlock(static_cast<unsigned>(i), walls[i]);
      output->GetMetaData(static_cast<unsigned>(i))->Set(vtkCompositeDataSet::NAME(), names[i].c_str());
    }
    return 1;
  }
  catch (const flowsurf::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
}
