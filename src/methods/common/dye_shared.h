// flowsurf — the dye's band over the pieces of a parallel render [issue 27 item 5]. Under
// MPI (ParaView's engine) each process holds a piece of the surface, and dye must cross the
// pieces' seams. Each process builds the band of its own piece on the grid of the whole
// surface's bounds (dye_band.h), and all exchange their candidates: at every cell the
// nearest closest point wins (on a tie the smaller triangle key, then the lower rank), so
// every process holds the band of the whole surface — the same closest points and
// velocities a single process computes, bit for bit — and advects all of it (DyeField).
// Velocities come from the process whose triangle holds cp(x).
// Cost: the band's triangle loop divided over the pieces; the candidates' exchange once per
// geometry (24 bytes per band voxel of the piece, to every process); 12 bytes per voxel a
// process won per velocity change (a new time step); each process then advects the whole
// band's active bricks (the dye's own work is not divided).
#pragma once

#include "core/mesh.h"
#include "methods/common/dye_band.h"
#include "methods/common/process_group.h"

#include <string>
#include <vector>

namespace flowsurf::methods {

class SharedDyeBand {
public:
    // Collective: every process of `group` with its piece and the same `grid`.
    SharedDyeBand(ProcessGroup& group, const core::SurfaceMesh& piece, const DyeGrid& grid);
    // The whole surface's band (moved out: call once); triangle and barycentric are empty
    // (they belong to the processes' pieces).
    DyeBand takeBand() { return std::move(band_); }
    // The tangential velocity of `field` at every voxel of the whole band (bandVelocity on
    // each process's own voxels, exchanged). Collective; `piece` the same geometry.
    std::vector<glm::vec3> velocity(const core::SurfaceMesh& piece, const std::string& field);

private:
    ProcessGroup& group_;
    DyeBand local_;                            // this piece's band
    size_t size_ = 0;                          // voxels of the whole band
    std::vector<uint32_t> won_;                // local voxels this process won, in send order
    std::vector<std::vector<uint32_t>> into_;  // per process: whole-band voxel of each value it sends
    DyeBand band_;
};

// The closest point of the whole surface (every process's piece) to p: what a dye source
// snaps to, on whichever process holds it. Collective when `group` has several processes.
glm::vec3 closestOnWholeSurface(ProcessGroup* group, const core::SurfaceMesh& piece, const glm::vec3& p);

}  // namespace flowsurf::methods
