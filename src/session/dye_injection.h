// flowsurf — dye injection [doc/algorithms.md §10], the part of session::Playback that releases ink: the
// options' sources (--dye, --dye-file) placed on the surface, the data time per dye step,
// and one methods::DyeField step per frame. The sources are read at every step, so a source
// that was not there before starts emitting at that step (dye changes apply live, effect
// None). Frame 0 emits; every later step first advects by the data time per frame.
#pragma once

#include "core/camera.h"
#include "dye/dye.h"
#include "session/animated_surface.h"
#include "session/options/options.h"

#include <memory>
#include <vector>

namespace flowsurf::session {

class DyeInjection {
public:
    // `group`: the processes rendering one view together (ParaView under MPI), or null.
    explicit DyeInjection(methods::ProcessGroup* group) : group_(group) {}

    // One dye step at this frame's camera and data time (nothing without sources).
    void step(const RenderOptions& o, AnimatedSurface& surface, const core::Camera& camera, double time,
              double perFrame);
    // Empty again, at step 0 (an animation starts over); the band stays.
    void restart();
    // The band is made again at the next step (a new surface: the geometry may differ);
    // the sources stay placed.
    void dropBand() { field_.reset(); }
    // What the methods draw at this camera; null before the first step has been taken.
    const methods::DyeView* view(const core::Camera& camera, const core::Viewport& viewport);

    // Null until a step had a source.
    const methods::DyeField* field() const { return field_.get(); }
    // Data time per dye step: the data's time per frame, or for steady data
    // --time-per-frame, or when 0 what moves the fastest dye --step-px pixels at the view
    // of the dye's first step.
    double timePerFrame() const { return dt_; }
    // A source as placed on the surface: the point snapped, radius and start resolved.
    struct Placed {
        methods::DyeSource source;  // as given
        int start = 0;              // dye step the source appeared at
        glm::vec3 posObj{0.0f};     // on the surface
        float radius = 0.0f;        // object units
    };
    const std::vector<Placed>& placed() const { return placed_; }

private:
    void makeBand(const RenderOptions& o, AnimatedSurface& surface, const core::SurfaceMesh& mesh,
                  const core::Camera& camera, double t, double perFrame);
    bool sameGeometryEverywhere(bool mine) const;  // `mine` and'ed over the process group
    std::vector<methods::DyeEmitter> emitters(const RenderOptions& o, const core::Camera& camera,
                                              const core::SurfaceMesh& mesh);

    methods::ProcessGroup* group_;
    std::unique_ptr<methods::DyeField> field_;
    std::vector<Placed> placed_;
    int steps_ = 0;                     // dye steps taken since the start
    double dt_ = 0.0, velocityTime_ = 0.0;
    methods::DyeView view_;
};

}  // namespace flowsurf::session
