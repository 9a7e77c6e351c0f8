#include "vtkFlowSurfRepresentation.h"

#include "vtkFlowSurfMapper.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"

#include <string>

vtkStandardNewMacro(vtkFlowSurfRepresentation);

vtkFlowSurfRepresentation::vtkFlowSurfRepresentation()
{
  // The full-resolution mapper draws the texture; the LOD mapper (interaction with LOD
  // on) stays ParaView's plain surface, as Surface LIC's default is.
  this->Mapper->Delete();
  this->FlowSurfMapper = vtkFlowSurfMapper::New();
  this->Mapper = this->FlowSurfMapper;
  vtkCompositeDataDisplayAttributes* attributes = vtkCompositeDataDisplayAttributes::New();
  this->FlowSurfMapper->SetCompositeDataDisplayAttributes(attributes);
  attributes->Delete();
  this->SetupDefaults();
}

vtkFlowSurfRepresentation::~vtkFlowSurfRepresentation() = default;

int vtkFlowSurfRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    // Every rank renders, with or without data, so image-space stages stay in step.
    outInfo->Set(vtkPVRenderView::RENDER_EMPTY_IMAGES(), 1);
  }
  if (request == vtkPVView::REQUEST_RENDER())
  {
    if (auto* view = vtkPVView::SafeDownCast(inInfo->Get(vtkPVView::VIEW())))
    {
      this->FlowSurfMapper->SetViewTime(view->GetViewTime());
    }
  }
  return 1;
}

int vtkFlowSurfRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkDataObject::GetData(inputVector[0], 0)
    : nullptr;
  vtkInformation* info = input ? input->GetInformation() : nullptr;
  const bool has = info && info->Has(vtkDataObject::DATA_TIME_STEP());
  this->FlowSurfMapper->SetPieceTime(has, has ? info->Get(vtkDataObject::DATA_TIME_STEP()) : 0.0);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

void vtkFlowSurfRepresentation::SetFlowSurfVectors(int, int, int, int, const char* name)
{
  this->FlowSurfMapper->SetVectorsName(name ? name : "");
  this->MarkModified();
}

void vtkFlowSurfRepresentation::SetFlowSurfOptionText(const char* option, const char* value)
{
  std::string error = this->FlowSurfMapper->SetOption(option ? option : "", value ? value : "");
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  this->MarkModified();
}

void vtkFlowSurfRepresentation::SetFlowSurfOptionInt(const char* option, int value)
{
  this->SetFlowSurfOptionText(option, std::to_string(value).c_str());
}

void vtkFlowSurfRepresentation::SetFlowSurfOptionDouble(const char* option, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  this->SetFlowSurfOptionText(option, text);
}

void vtkFlowSurfRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
