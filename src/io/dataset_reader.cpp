// readDataset: pick the reader (vtk_sources), then run each time step through the
// surface pipeline (surface_pipeline). Errors VTK only prints become FormatErrors.
#include "io/dataset_reader.h"

#include "io/surface_pipeline.h"
#include "io/vtk_messages.h"
#include "io/vtk_sources.h"

#include <algorithm>

namespace flowsurf::io {

core::Dataset readDataset(const std::string& path, const ReadOptions& options) {
    detail::VtkMessageTrap trap;
    auto source = detail::openSource(path, trap);
    size_t count = source->stepCount();
    if (options.maxSteps > 0) count = std::min(count, options.maxSteps);

    core::Dataset dataset;
    dataset.source = path;
    dataset.steps.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        vtkSmartPointer<vtkDataObject> raw = source->readStep(i);
        core::TimeStep step;
        step.time = source->times().empty() ? 0.0 : source->times()[i];
        step.mesh = detail::readSurfaceMesh(raw, trap, detail::stepLabel(path, *source, i));
        dataset.steps.push_back(std::move(step));
    }
    return dataset;
}

}  // namespace flowsurf::io
