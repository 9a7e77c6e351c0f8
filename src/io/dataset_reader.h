// flowsurf — reading surfaces with vector fields through VTK 9.
// Formats: .vtp .vtu .vtk (surface extracted, triangulated, cell data -> point data),
// .ply .obj .stl (geometry only), OpenFOAM (.foam: boundary patches), Exodus (.e .ex2),
// EnSight (.case), and a ParaView .pvd collection.
#pragma once

#include "core/mesh.h"

#include <string>
#include <vector>

namespace flowsurf::io {

struct ReadOptions {
    // Keep at most this many time steps resident (0 = all). Streaming comes later.
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
};
struct FileInfo {
    std::string path;
    std::string format;            // e.g. "VTK XML PolyData"
    size_t points = 0, triangles = 0;  // after triangulation, first time step
    std::vector<ArrayInfo> arrays;
    std::vector<double> times;     // empty or one entry for a single step
    core::Bounds bounds;
};
FileInfo inspectFile(const std::string& path);
std::string formatFileInfo(const FileInfo& info);

}  // namespace flowsurf::io
