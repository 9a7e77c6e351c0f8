// The flow topology as VTK PolyData (.vtp) through VTK's own XML writer, to a temporary
// file renamed on success.
#include "io/skeleton_writer.h"

#include "core/errors.h"
#include "io/skeleton_polydata.h"
#include "io/temp_file.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <unistd.h>

namespace flowsurf::io {

void writeSkeletonVtp(const std::string& path, const skeleton::Skeleton& s, const SkeletonSource& source) {
    (void)source;
    vtkSmartPointer<vtkPolyData> poly = skeletonPolyData(s);
    detail::TempFile tmp(path, ".vtp");
    ::close(tmp.fd());
    tmp.fd() = -1;
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(tmp.path().c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToBinary();
    if (writer->Write() != 1) throw IoError(path + ": cannot write (VTK's XML writer failed)");
    tmp.commit();
}

}  // namespace flowsurf::io
