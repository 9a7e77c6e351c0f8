#include "methods/image_space/camera_motion.h"

namespace flowsurf::methods {

MotionPlan CameraMotion::plan(const core::Camera& camera) {
    const bool moving = havePrev_ && !core::sameCamera(camera, prev_);
    MotionPlan p;
    p.sourceCamera = camera;
    switch (remedy_) {
        case CameraMoveRemedy::None: break;
        case CameraMoveRemedy::Translate:
            if (havePrev_) p.sourceCamera = prev_;
            break;
        case CameraMoveRemedy::Freeze:
            if (moving) {
                if (!frozen_) {
                    frozen_ = true;
                    freezeCamera_ = prev_;
                    p.freezeStarts = true;
                }
                p.sourceCamera = freezeCamera_;
                p.advect = false;
            } else {
                // Still again: the last displayed texture was mapped into this view.
                frozen_ = false;
            }
            break;
    }
    prev_ = camera;
    havePrev_ = true;
    return p;
}

}  // namespace flowsurf::methods
