// flowsurf — dye injection [doc/algorithms.md §10] (dye_injection.h): the sources placed on the surface,
// the data time per dye step, and one step per frame (methods::DyeField).
#include "session/dye_injection.h"

#include "dye/dye_band.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::session {

namespace {
// Voxel size of the dye's band in pixels of the view the dye starts at: the band resolves
// what that view shows (the default radius, methods::kDyeRadiusPx, is 3 voxels).
constexpr float kDyeVoxelPx = 2.0f;

// Image scale at p: pixels per object unit across the view.
float pixelsPerUnitAt(const core::Camera& camera, const core::Viewport& viewport, const glm::vec3& p) {
    if (camera.orthographic()) return float(viewport.height) / camera.orthoHeight;
    const float dist = glm::dot(p - camera.eye, glm::normalize(camera.target - camera.eye));
    return float(viewport.height) /
           (2.0f * std::max(dist, camera.nearPlane) * std::tan(glm::radians(camera.fovDeg) * 0.5f));
}
}  // namespace

bool DyeInjection::sameGeometryEverywhere(bool mine) const {
    if (!group_ || group_->size() < 2) return mine;
    int32_t same = mine ? 1 : 0;
    group_->minInPlace(std::span<int32_t>(&same, 1));
    return same != 0;
}

void DyeInjection::restart() {
    if (field_) field_->clear();
    placed_.clear();
    steps_ = 0;
}

const methods::DyeView* DyeInjection::view(const core::Camera& camera, const core::Viewport& viewport) {
    if (!field_ || steps_ == 0) return nullptr;
    view_ = field_->view(camera, viewport);
    return &view_;
}

std::vector<methods::DyeEmitter> DyeInjection::emitters(const RenderOptions& o, const core::Camera& camera,
                                                        const core::SurfaceMesh& mesh) {
    std::vector<methods::DyeSource> wanted = o.dye;
    wanted.insert(wanted.end(), o.dyeFileSources.begin(), o.dyeFileSources.end());
    // Keep the sources still asked for (with their start), place the new ones now.
    std::vector<Placed> placed;
    for (const methods::DyeSource& s : wanted) {
        auto it = std::find_if(placed_.begin(), placed_.end(), [&](const Placed& p) { return p.source == s; });
        if (it != placed_.end()) {
            placed.push_back(*it);
            placed_.erase(it);  // two equal sources stay two
            continue;
        }
        Placed p;
        p.source = s;
        p.start = steps_;
        p.posObj = methods::closestOnWholeSurface(group_, mesh, s.point);
        p.radius = s.radius > 0.0f ? s.radius : methods::kDyeRadiusPx / pixelsPerUnitAt(camera, o.size, p.posObj);
        placed.push_back(p);
    }
    placed_ = std::move(placed);

    std::vector<methods::DyeEmitter> out;
    for (const Placed& p : placed_) {
        const int f = steps_ - p.start;  // steps since the source appeared
        const int stop = p.source.stop >= 0 ? p.source.stop
                         : o.dyeRelease > 0 ? p.source.start + o.dyeRelease
                                            : -1;
        if (f >= p.source.start && (stop < 0 || f < stop)) out.push_back({p.posObj, p.radius, p.source.color});
    }
    return out;
}

void DyeInjection::makeBand(const RenderOptions& o, AnimatedSurface& surface, const core::SurfaceMesh& mesh,
                            const core::Camera& camera, double t, double perFrame) {
    const methods::SurfaceGpu& s = surface.atTime(t);
    const float h = kDyeVoxelPx / core::maxPixelsPerUnit(camera, o.size, s.bounds());
    // Under tiles a process shows its own piece only: it advects that part of the band.
    const bool divide = o.params.common.parallel == methods::ParallelMode::Tiles;
    field_ = std::make_unique<methods::DyeField>(mesh, surface.field(), s.bounds(), h, group_, divide);
    velocityTime_ = t;
    if (surface.unsteady()) {
        dt_ = perFrame;
    } else if (o.timePerFrame > 0.0) {
        dt_ = o.timePerFrame;
    } else {
        // The fastest dye (98th percentile of the speed, as the colour map's top) moves
        // --step-px pixels per frame at this view.
        const float speed = s.colorSpeedMax() > 0.0f ? s.colorSpeedMax() : field_->maxSpeed();
        const float pxPerUnit = core::maxPixelsPerUnit(camera, o.size, s.bounds());
        dt_ = speed > 0.0f ? o.params.common.stepPx / (speed * pxPerUnit) : 0.0;
    }
}

void DyeInjection::step(const RenderOptions& o, AnimatedSurface& surface, const core::Camera& camera, double time,
                        double perFrame) {
    if (!field_ && o.dye.empty() && o.dyeFileSources.empty()) return;
    const double t = surface.unsteady() ? time : 0.0;
    const core::SurfaceMesh& mesh = surface.meshAtTime(t);
    // The band: made at the first step, again when the geometry changes (the dye with it).
    // Split over processes (ParaView under MPI) each holds a piece and every one the whole
    // band (dye/dye_shared.h): made again when any piece changed.
    if (field_ && !sameGeometryEverywhere(field_->sameGeometry(mesh))) {
        field_.reset();
        restart();
    }
    if (!field_) makeBand(o, surface, mesh, camera, t, perFrame);
    if (surface.unsteady()) {
        dt_ = perFrame;
        if (t != velocityTime_) {  // each step's field (interpolated as the surface is)
            field_->setVelocity(mesh, surface.field());
            velocityTime_ = t;
        }
    }
    const std::vector<methods::DyeEmitter> emitting = emitters(o, camera, mesh);
    field_->step(steps_ > 0 ? float(dt_) : 0.0f, o.dyeDecay, emitting);
    ++steps_;
}

}  // namespace flowsurf::session
