// flowsurf — the "FlowSurf" representation: ParaView's Surface representation with
// vtkFlowSurfMapper in place of its mapper (as ParaView's Surface LIC does). Its
// properties (FlowSurf.xml) are generated from the option table; each calls one of the
// SetFlowSurfOption* setters with the option's name (the XML's initial_string).
#ifndef vtkFlowSurfRepresentation_h
#define vtkFlowSurfRepresentation_h

#include "FlowSurfRepresentationsModule.h"  // for export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkFlowSurfMapper;

class FLOWSURFREPRESENTATIONS_EXPORT vtkFlowSurfRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkFlowSurfRepresentation* New();
  vtkTypeMacro(vtkFlowSurfRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Passes the view time to the mapper and asks for empty images on empty ranks.
  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

  // FlowSurfVectors: the point array shown (as ColorArrayName, five elements).
  void SetFlowSurfVectors(int, int, int, int attributeMode, const char* name);
  // One option of src/session/options.cpp by its command-line name ("filter-length").
  void SetFlowSurfOptionText(const char* option, const char* value);
  void SetFlowSurfOptionInt(const char* option, int value);
  void SetFlowSurfOptionDouble(const char* option, double value);

protected:
  vtkFlowSurfRepresentation();
  ~vtkFlowSurfRepresentation() override;

  // Hands the piece's data time to the mapper (ParaView's delivery drops it).
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkFlowSurfMapper* FlowSurfMapper;

private:
  vtkFlowSurfRepresentation(const vtkFlowSurfRepresentation&) = delete;
  void operator=(const vtkFlowSurfRepresentation&) = delete;
};

#endif
