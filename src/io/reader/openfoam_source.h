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

// Which layout `--foam-case auto` reads: the decomposed one when processor* directories
// exist and the case folder has no mesh or fewer time directories than processor0 (a
// case run in parallel and not, or only partly, reconstructed); else the reconstructed.
// Throws ConfigError for a choice that is not auto/reconstructed/decomposed, or
// "decomposed" without processor* directories.
bool readsDecomposed(const std::string& casePath, const std::string& choice);

// Throws IoError/FormatError as openSource, ConfigError for --patches or --foam-case.
std::unique_ptr<StepSource> openOpenFoam(const std::string& path, VtkMessageTrap& trap, const SourceOptions& options);

// "U [m/s]" -> "U" with units "m/s" (AddDimensionsToArrayNames' suffix); false when the
// name carries no such suffix.
bool splitUnitsSuffix(const std::string& name, std::string& bare, std::string& units);

}  // namespace flowsurf::io::detail
