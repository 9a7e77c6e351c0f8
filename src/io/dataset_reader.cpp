// readDataset: every step read in the reader process (reader_process.h), where the reader
// is picked (vtk_sources) and each step runs through the surface pipeline.
#include "io/dataset_reader.h"

#include "io/reader_process.h"

namespace flowsurf::io {

core::Dataset readDataset(const std::string& path, const ReadOptions& options) {
    return detail::ReaderProcess().readDataset(path, options.maxSteps);
}

}  // namespace flowsurf::io
