// VTK's error reports reach a VtkMessageTrap, not the terminal: from the reader itself
// (an observer) and from parsers created inside it (the output window), in nested scopes
// (a .pvd's member read inside the collection's scope) as in the outer one.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/vtk_messages.h"
#include "io/reader/vtk_sources.h"

#include "test_io_common.h"

#include <vtkXMLPolyDataWriter.h>

using namespace flowsurf;
using namespace flowsurf::testing_io;

TEST(IoReaders, MessageTrapsCatchVtkErrorsInNestedScopes) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(makeGrid(2, 2));
    w->SetFileName(dir.file("good.vtp").c_str());
    ASSERT_EQ(w->Write(), 1);
    writeText(dir.file("bad.vtp"), "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOf");

    ::testing::internal::CaptureStderr();
    io::detail::VtkMessageTrap outer, inner;
    std::string message;
    {
        io::detail::VtkMessageTrap::Active scope(outer);
        auto source = io::detail::openSource(dir.file("good.vtp"), outer);
        try {
            io::detail::openSource(dir.file("bad.vtp"), inner);
        } catch (const FormatError& e) {
            message = e.what();
        }
        EXPECT_FALSE(outer.hasError());  // the inner scope's words stayed there
        EXPECT_EQ(source->stepCount(), 1u);
    }
    // The XML parser inside the reader has no observer: its words came through the
    // output window.
    EXPECT_NE(message.find("bad.vtp"), std::string::npos) << message;
    EXPECT_NE(message.find("Error parsing XML"), std::string::npos) << message;
    EXPECT_THROW(io::readDataset(dir.file("bad.vtp")), FormatError);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}
