// flowsurf — the interaction remedies of [L §IV-I] (doc/algorithms.md §5), shared by the
// image-space methods: per frame, which camera maps the previous texture, and whether
// this frame advects and injects noise or only re-maps a frozen texture.
#pragma once

#include "core/camera.h"
#include "params/params.h"

namespace flowsurf::methods {

struct MotionPlan {
    core::Camera sourceCamera;  // projects pathline points into the source texture
    bool advect = true;         // false: frozen (dt = 0, no noise, source kept)
    bool freezeStarts = false;  // first frozen frame: keep the current texture as source
};

class CameraMotion {
public:
    explicit CameraMotion(CameraMoveRemedy remedy) : remedy_(remedy) {}
    MotionPlan plan(const core::Camera& camera);

private:
    CameraMoveRemedy remedy_;
    bool havePrev_ = false, frozen_ = false;
    core::Camera prev_, freezeCamera_;
};

}  // namespace flowsurf::methods
