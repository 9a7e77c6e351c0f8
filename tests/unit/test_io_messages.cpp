// VTK's error reports reach a VtkMessageTrap, not the terminal, also when traps live
// long, end in any order, or are used from a worker thread (as a lazily read series
// does with its prefetching StepStream).
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/vtk_messages.h"
#include "io/reader/vtk_sources.h"

#include "test_io_common.h"

#include <vtkOutputWindow.h>
#include <vtkXMLPolyDataWriter.h>

#include <memory>
#include <thread>

using namespace flowsurf;
using namespace flowsurf::testing_io;

TEST(IoReaders, MessageTrapsEndInAnyOrderAndWorkOnWorkerThreads) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(makeGrid(2, 2));
    w->SetFileName(dir.file("good.vtp").c_str());
    ASSERT_EQ(w->Write(), 1);
    writeText(dir.file("bad.vtp"), "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOf");
    vtkOutputWindow* before = vtkOutputWindow::GetInstance();

    ::testing::internal::CaptureStderr();
    auto first = std::make_unique<io::detail::VtkMessageTrap>();
    auto second = std::make_unique<io::detail::VtkMessageTrap>();
    auto source = io::detail::openSource(dir.file("good.vtp"), *first);
    std::string message;
    std::thread worker([&] {
        try {
            io::detail::openSource(dir.file("bad.vtp"), *second);
        } catch (const FormatError& e) {
            message = e.what();
        }
    });
    worker.join();
    // The XML parser inside the reader has no observer: its words came through the
    // capturing output window, on the worker thread.
    EXPECT_NE(message.find("bad.vtp"), std::string::npos) << message;
    EXPECT_NE(message.find("Error parsing XML"), std::string::npos) << message;

    // The first trap goes before the second: nothing may point at it afterwards.
    source.reset();
    first.reset();
    EXPECT_EQ(io::detail::openSource(dir.file("good.vtp"), *second)->stepCount(), 1u);
    second.reset();
    EXPECT_THROW(io::readDataset(dir.file("bad.vtp")), FormatError);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(vtkOutputWindow::GetInstance(), before);  // put back after the last scope
}
