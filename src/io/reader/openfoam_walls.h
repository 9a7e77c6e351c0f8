// flowsurf — skin-friction on an OpenFOAM case (private to src/io, used by
// openfoam_source.cpp): which patches are walls (constant/polyMesh/boundary), the case's
// kinematic viscosity (constant/transportProperties or physicalProperties), and the step's
// patches given the derived array from the internal mesh, which is then dropped.
#pragma once

#include "io/reader/skin_friction.h"

#include <filesystem>
#include <map>
#include <string>

class vtkDataObject;

namespace flowsurf::io::detail {

// The patches' types by name from `meshDir`/boundary ("wall", "patch", "empty", ...); empty
// when the file is missing, compressed or not parsed.
std::map<std::string, std::string> readPatchTypes(const std::filesystem::path& meshDir);

// The patches' face counts (nFaces) by name from `meshDir`/boundary, as readPatchTypes.
std::map<std::string, size_t> readPatchFaceCounts(const std::filesystem::path& meshDir);

// `nu` of `caseDir`/constant/transportProperties, else of physicalProperties (as
// `nu 1e-05;`, `nu [0 2 -1 0 0 0 0] 1e-05;` or `nu nu [..] 1e-05;`); 0 when neither gives one.
// `from` is set to the file it came from.
double readCaseViscosity(const std::filesystem::path& caseDir, std::string& from);

// A patch type OpenFOAM treats as a wall: wall, or a kind of it (mappedWall).
bool isFoamWallType(const std::string& type);

// How a case's steps get skin-friction.
struct FoamWalls {
    SkinFrictionOptions options;                 // viscosity resolved; wall velocity "U", ν_t "nut"
    std::map<std::string, std::string> types;    // patch types (empty: every patch is a wall)
    std::string described;                       // the viscosity and where it came from, for the format line
};

// Adds skin-friction to every wall patch of `step` (the reader's output, its leaves already
// the source's own copies): computed from the "internalMesh" leaf, which is then removed;
// other patches get zero vectors (no wall, no stress, as OpenFOAM's function object writes).
// Throws as addSkinFriction; FormatError when the step has no internal mesh or no wall patch.
void addFoamSkinFriction(vtkDataObject& step, const FoamWalls& walls, const std::string& where);

}  // namespace flowsurf::io::detail
