// flowsurf — OpenFOAM cases through VTK's reader (private to src/io): the boundary
// patches (--patches) of a reconstructed case or of a decomposed one (processor*
// directories, --foam-case), every time directory a step (0/ included), points re-read
// for time directories that have polyMesh/points (moving meshes), and each field's units
// from its `dimensions` (VTK's "m/s" notation, kept on the arrays as UNITS_LABEL).
#pragma once

#include "io/dataset_reader.h"
#include "io/reader/vtk_sources.h"

#include <memory>
#include <string>

namespace flowsurf::io::detail {

// Throws IoError/FormatError as openSource, ConfigError for --patches or --foam-case.
// `format` ("OpenFOAM case") names it in messages, with the layout read.
std::unique_ptr<StepSource> openOpenFoam(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                         const SourceOptions& options);

}  // namespace flowsurf::io::detail
