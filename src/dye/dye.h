// flowsurf — dye on the surface [doc/algorithms.md §10]: concentration kept in object space on the narrow
// band of dye_band.h, advected on the GPU by the surface's tangential velocity and shown by
// every method's overlay at the visible surface point of each pixel (so it survives camera
// motion, zoom and occlusion). Method-independent: session::Playback owns one and steps it
// once per animation frame.
// Advection: semi-Lagrangian on the closest points, u'(x) = u(cp(x) - v dt) (closest point
// method), with the MacCormack correction and the min/max limiter of [Selle et al. 2008,
// J. Sci. Comput. 35] for second-order accuracy and little numerical diffusion.
// Values: RGBA32F per band voxel, premultiplied (rgb = colour x concentration, a = concentration).
#pragma once

#include "core/camera.h"
#include "core/mesh.h"
#include "dye/dye_band.h"
#include "dye/dye_shared.h"
#include "gl/objects.h"
#include "gpu/shader_limits.h"

#include <memory>
#include <string>
#include <vector>

namespace flowsurf::methods {

// A source emitting this frame, on the surface.
struct DyeEmitter {
    glm::vec3 posObj{0.0f};
    float radius = 0.0f;  // object units
    glm::vec3 color{1.0f};
};

// What the overlay needs to sample the dye at the visible surface (FrameInput::dye).
struct DyeView {
    GLuint index = 0;       // R32I 3D texture
    GLuint values = 0;      // SSBO
    int slot = 0;           // first vec4 of the current values
    DyeGrid grid;
    glm::mat4 invViewProj{1.0f};  // window -> object space of this frame's camera
};

class DyeField {
public:
    // The band of `mesh` on a grid over `bounds` (the whole surface's) with voxel size `h`
    // (object units), and the velocity of `field`. With a group of several processes `mesh`
    // is this process's piece and the band the whole surface's (dye_shared.h; collective,
    // as are setVelocity and the construction's sameGeometry decision in session::Playback).
    // Needs a current GL context.
    // `divide`: in a group, each process advects only its piece's part of the band
    // (dye_shared.h; for `tiles`, where a process shows its own piece only).
    DyeField(const core::SurfaceMesh& mesh, const std::string& field, const core::Bounds& bounds, float h,
             ProcessGroup* group = nullptr, bool divide = false);

    // True if `mesh` has the triangles the band was built from and its positions within a
    // tenth of a voxel (a new time step of the same geometry: only the velocity changes).
    bool sameGeometry(const core::SurfaceMesh& mesh) const;
    void setVelocity(const core::SurfaceMesh& mesh, const std::string& field);
    void clear();
    // One frame: advect by `dt` data time (0: none), decay by exp(-decay dt), then emit.
    void step(float dt, float decay, const std::vector<DyeEmitter>& emitters);
    DyeView view(const core::Camera& camera, const core::Viewport& viewport) const;
    const DyeBand& band() const { return band_; }
    // Largest band velocity (object units per data time).
    float maxSpeed() const { return maxSpeed_; }
    // The current values read back (tests): RGBA per band voxel (divided: valid on the
    // bricks of this process's piece, pieceBricks()).
    std::vector<glm::vec4> readValues() const;
    // Per brick: 1 where this process advects (all of them unless divided).
    std::vector<uint8_t> advectedBricks() const;
    // The last step: band voxels this process advected, and the halo's bytes it sent.
    size_t advectedVoxels() const { return advectedVoxels_; }
    size_t haloBytesSent() const { return haloBytesSent_; }

private:
    void pass(int pass, float dt, float decayFactor, int emitterCount, int count);
    // The bricks the next step can change: those that held dye in either of the last two
    // steps (the two value slots) grown by how far the dye reaches in a step, and those the
    // emitters cover. The rest hold no dye and stay as they are. Their voxels are listed
    // for the passes: first those this process advects (pass 1), then the others within
    // `readReach` bricks of those (pass 0 too: pass 1 reads u^ there).
    struct Active {
        std::vector<uint8_t> bricks;  // per brick, the same on every process
        bool any = false;
        size_t advected = 0, forward = 0;  // voxels listed for pass 1, for pass 0
    };
    Active listActive(float dt, const std::vector<DyeEmitter>& emitters, int readReach);
    // Divided: the values of the current slot this process reads in the step and does not
    // advect, from their keepers (collective).
    void receiveHalo(const std::vector<uint8_t>& active, int readReach);

    std::unique_ptr<SharedDyeBand> shared_;  // in a parallel render
    bool divided_ = false;
    DyeBand band_;
    std::vector<glm::vec3> positions_;
    std::vector<glm::uvec3> triangles_;
    gl::Program program_;
    gl::Handle<gl::detail::deleteTexture> indexTexture_;
    gl::Buffer bandData_, values_, emitters_, departures_, flags_, active_;
    std::vector<uint32_t> hadDye_, hadDyeBefore_;  // per brick: the flags of the last two steps
    float departureDt_ = 0.0f;  // dt the departure points are for (0: stale)
    int current_ = 0;  // slot of the current values (0 or 1); slot 2 holds the forward step
    float maxSpeed_ = 0.0f;
    // Divided: per value slot and brick, 1 where this process holds a halo copy that may
    // not be zero (it is cleared when the brick has no dye left and is read again).
    std::vector<uint8_t> haloHeld_[2];
    size_t advectedVoxels_ = 0, haloBytesSent_ = 0;
};

}  // namespace flowsurf::methods
