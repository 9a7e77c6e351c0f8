// flowsurf — `flowsurf info`'s look into a file, done in the reader process (private to src/io).
#pragma once

#include "io/dataset_reader.h"

namespace flowsurf::io::detail {

// Reads the first time step of `path` in this process (through VTK). Throws like readDataset.
FileInfo inspectFileHere(const std::string& path, const SourceOptions& options = {});

}  // namespace flowsurf::io::detail
