// flowsurf — the derived field `skin-friction`: the wall shear stress the fluid exerts on a
// wall, estimated from the velocity in the volume cell next to each wall face (private to
// src/io, run in the reader process where the volume is read). For any VTK volume data set
// (an OpenFOAM internal mesh, an unstructured or structured grid, a CGNS zone) and wall
// surfaces whose points are points of that volume (its patches, or its boundary surface).
//
// Per wall face f with owner cell c (the volume cell holding all of f's points):
//   n  = unit normal of f, towards c's centre;   d = n · (x_c − x_f)  (wall distance)
//   Δu = u_c − u_w                                (u_w: the wall's velocity, zero at rest)
//   τ  = ν_eff · (Δu − (Δu·n) n) / d              (first-order one-sided wall gradient)
// ν_eff = ν (+ ν_t on the wall face where the wall carries it, e.g. OpenFOAM's nut from wall
// functions); without ν the factor is 1: τ is the tangential velocity gradient in 1/s, the
// direction and a relative magnitude. τ points with the near-wall flow (the stress on the
// wall; OpenFOAM's wallShearStress is the stress on the fluid, −τ).
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkDataSet;

namespace flowsurf::io::detail {

inline constexpr const char* kSkinFrictionName = "skin-friction";

struct SkinFrictionOptions {
    std::string velocity;            // the volume's velocity array (cell or point data); empty: findVelocityArray
    double viscosity = 0.0;          // kinematic ν in m²/s; 0: unknown (relative magnitude, 1/s)
    std::string wallVelocity;        // the walls' own per-face velocity (cell data; OpenFOAM's patch U); empty or
                                     // absent on a wall: the volume's point velocity on the face, else at rest
    std::string turbulentViscosity;  // the walls' per-face ν_t added to ν (OpenFOAM's nut); empty or absent: none
    // Where warnings go (the reader: warnOnce; null: dropped). Nothing else here is flowsurf's
    // but its error types, so a VTK filter elsewhere (ParaView's) can compile this file too.
    std::function<void(const std::string&)> warn;
};

// The units label of the derived array: "m2/s2" (VTK's notation of OpenFOAM's units: kinematic stress, as OpenFOAM's
// incompressible wallShearStress) with a viscosity, else a label saying the magnitude is relative.
std::string skinFrictionUnits(double viscosity);

// The volume's velocity: a 3-component cell or point array named U, velocity or vel (any
// case), or "" when there is none.
std::string findVelocityArray(vtkDataSet* volume);

// Whether `data` has cells of dimension 3 (a volume to take the wall gradient in).
bool hasVolumeCells(vtkDataSet* data);

// Adds the 3-component cell array kSkinFrictionName (with its UNITS_LABEL) to each of
// `walls`, whose faces are faces of `volume`'s cells (points matched by their coordinates, so
// patches read apart from the volume, or a decomposed case's pieces appended, still match).
// `wallNames` name the walls in messages ("patch 'ground'"), `where` the file.
// Throws FieldError when the volume has no such velocity, FormatError when a wall face lies at
// zero distance from its cell's centre or no wall face matches a volume cell; faces of a wall
// that match no cell get a zero vector and one warning.
void addSkinFriction(vtkDataSet* volume, const std::vector<vtkPolyData*>& walls,
                     const std::vector<std::string>& wallNames, const SkinFrictionOptions& options,
                     const std::string& where);

// As addSkinFriction for one wall whose owner cells are known, no coordinates matched: face f
// of `wall` is a face of volume cell cells[f] (-1: of none; zero there and one warning) over
// the volume points facePoints[faceOffsets[f] .. faceOffsets[f+1]) (CGNS: a BC's faces as zone
// vertex ids and wallCells()). Throws as addSkinFriction, and FormatError when no face has a cell.
void addSkinFrictionOnCells(vtkDataSet* volume, vtkPolyData* wall, const std::vector<vtkIdType>& cells,
                            const std::vector<vtkIdType>& faceOffsets, const std::vector<vtkIdType>& facePoints,
                            const std::string& wallName, const SkinFrictionOptions& options, const std::string& where);

// kSkinFrictionName as zeros on a surface that is no wall (an inflow patch read beside the
// walls), so every block of the surface carries the field.
void addZeroSkinFriction(vtkDataSet* surface, double viscosity);

// A volume's boundary surface (vtkDataSetSurfaceFilter: the faces of one cell only, with the
// volume's point and cell data) with kSkinFrictionName on it: the wall of a VTK volume file,
// where every boundary face is taken as a wall at rest unless its points carry a velocity.
vtkSmartPointer<vtkPolyData> newBoundaryWithSkinFriction(vtkDataSet* volume, const SkinFrictionOptions& options,
                                                         const std::string& where);

}  // namespace flowsurf::io::detail
