// flowsurf — the dye's band over the pieces of a parallel render [docs/parallel.md]. Under
// MPI (ParaView's engine) each process holds a piece of the surface, and dye must cross the
// pieces' seams. Each process builds the band of its own piece on the grid of the whole
// surface's bounds (dye_band.h), and all exchange their candidates: at every cell the
// nearest closest point wins (on a tie the smaller triangle key, then the lower rank), so
// every process holds the band of the whole surface — the same closest points and
// velocities a single process computes, bit for bit — and advects all of it (DyeField).
// Velocities come from the process whose triangle holds cp(x).
// Divided advection (CommonParams::parallel = tiles, where each process shows only its own
// piece's fragments): each process advects the bricks its own piece's band touches (at a
// seam two processes advect the same brick, to the same values) and, before a step,
// receives the values it reads around them — its halo, as far as the step reaches — from
// the lowest process that advects them (the brick's keeper). Only bricks holding dye
// travel (a brick without dye is all zeros, kDyeVisible). Under `replicate` every process
// shows the whole surface and advects the whole band.
// Cost: the band's triangle loop divided over the pieces; the candidates' exchange once per
// geometry (24 bytes per band voxel of the piece, to every process); 12 bytes per voxel a
// process won per velocity change (a new time step); per divided step the active bricks
// of the piece's band (and what a step reaches from them) and 16 bytes per voxel of the
// halo's bricks holding dye.
#pragma once

#include "core/mesh.h"
#include "dye/dye_band.h"
#include "parallel/process_group.h"

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

    // Per brick of the whole band: 1 where process `rank`'s piece's band has a voxel (the
    // bricks it advects when divided).
    const std::vector<uint8_t>& pieceBricks(int rank) const { return pieceBricks_[size_t(rank)]; }
    // The lowest process whose piece's band touches brick b (-1: none).
    int keeper(size_t b) const { return keeper_[b]; }
    ProcessGroup& group() { return group_; }

private:
    ProcessGroup& group_;
    DyeBand local_;                            // this piece's band
    size_t size_ = 0;                          // voxels of the whole band
    std::vector<uint32_t> won_;                // local voxels this process won, in send order
    std::vector<std::vector<uint32_t>> into_;  // per process: whole-band voxel of each value it sends
    std::vector<std::vector<uint8_t>> pieceBricks_;  // per process, per brick
    std::vector<int> keeper_;                        // per brick
    DyeBand band_;
};

// Per brick of a grid of `dims` bricks: 1 within `reach` bricks (per axis) of a brick
// where `a` and `b` are both 1.
std::vector<uint8_t> dilateBoth(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, glm::ivec3 dims, int reach);

// The closest point of the whole surface (every process's piece) to p: what a dye source
// snaps to, on whichever process holds it. Collective when `group` has several processes.
glm::vec3 closestOnWholeSurface(ProcessGroup* group, const core::SurfaceMesh& piece, const glm::vec3& p);

}  // namespace flowsurf::methods
