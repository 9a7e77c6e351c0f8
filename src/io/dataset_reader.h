// flowsurf — reading surfaces with vector fields through VTK 9.
// Formats: .vtp .vtu .vtk (surface extracted, triangulated, cell data -> point data),
// .ply .obj .stl (geometry only), OpenFOAM (.foam: boundary patches), CGNS (.cgns: the wall
// patches of volumes), Exodus (.e .ex2), EnSight (.case), and a ParaView .pvd collection.
#pragma once

#include "core/mesh.h"
#include "io/source_options.h"

#include <string>
#include <vector>

namespace flowsurf::io {

struct ReadOptions {
    // Read only the first this many time steps (0 = all); every step read stays in the
    // Dataset. A long series is better opened with openInput, which loads steps on demand.
    size_t maxSteps = 0;
};

// Reads every time step of `path` into a Dataset. Each step's mesh holds all point
// arrays with 3 components as fields, normals (from the file's point normals, else
// computed), and only triangles. Validates with core::validateMesh.
// Throws IoError (cannot open/read), FormatError (malformed, truncated, empty, NaN...).
core::Dataset readDataset(const std::string& path, const ReadOptions& options = {});

// What `flowsurf info FILE` prints.
struct ArrayInfo {
    std::string name;
    int components = 0;
    bool pointData = true;  // false: cell data (converted to point data on read)
    double rangeMin = 0, rangeMax = 0;  // of the magnitude for vectors
    std::string units;                  // e.g. "m/s" (OpenFOAM dimensions); empty when unknown
};
// A part of the surface (an OpenFOAM boundary patch, an Exodus block...): its name and
// faces, and the names of the arrays it carries (a field may be missing on some).
struct PartInfo {
    std::string name;
    size_t faces = 0;
    std::vector<std::string> arrays;
};
// A boundary condition of a CGNS volume zone, read or not: what --patches chooses from.
struct PatchInfo {
    std::string name;    // the BC's name ("ZONE/BC" when the file has several zones)
    std::string type;    // its BC type ("BCWall"), its family's when the BC is FamilySpecified
    std::string family;  // empty when none
    size_t faces = 0;
    bool read = false;   // part of the surface read: a wall by default, else --patches' choice
};
struct FileInfo {
    std::string path;
    std::string format;            // e.g. "VTK XML PolyData"
    size_t points = 0, triangles = 0;  // after triangulation, first time step
    std::vector<ArrayInfo> arrays;
    std::vector<PartInfo> parts;   // more than one only for composite data (patches, blocks)
    std::vector<double> times;     // empty or one entry for a single step
    core::Bounds bounds;
    std::vector<PatchInfo> patches;  // every boundary condition, where the format has them (CGNS)
    // How --field skin-friction is derived here ("from U in the cells next to ..."), "not
    // available: why" for a volume without velocity or an OpenFOAM case lacking what it needs;
    // empty for surface files.
    std::string skinFriction;
};
FileInfo inspectFile(const std::string& path, const SourceOptions& options = {});
std::string formatFileInfo(const FileInfo& info);

}  // namespace flowsurf::io
