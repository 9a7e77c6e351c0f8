// flowsurf — Playback's dye [issue 20]: the sources of the options placed on the surface,
// the data time per dye step, and one step per frame (methods::DyeField).
#include "session/playback.h"

#include "methods/common/dye_band.h"

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

bool sameSource(const methods::DyeSource& a, const methods::DyeSource& b) { return a == b; }
}  // namespace

bool Playback::sameGeometryEverywhere(bool mine) const {
    if (!group_ || group_->size() < 2) return mine;
    int32_t same = mine ? 1 : 0;
    group_->minInPlace(std::span<int32_t>(&same, 1));
    return same != 0;
}

void Playback::resetDye() {
    if (dye_) dye_->clear();
    placedDye_.clear();
    dyeFrame_ = 0;
}

std::vector<methods::DyeEmitter> Playback::dyeEmitters(const core::Camera& camera, const core::SurfaceMesh& mesh) {
    std::vector<methods::DyeSource> wanted = options_.dye;
    wanted.insert(wanted.end(), options_.dyeFileSources.begin(), options_.dyeFileSources.end());
    // Keep the sources still asked for (with their start), place the new ones now.
    std::vector<PlacedDye> placed;
    for (const methods::DyeSource& s : wanted) {
        auto it = std::find_if(placedDye_.begin(), placedDye_.end(),
                               [&](const PlacedDye& p) { return sameSource(p.source, s); });
        if (it != placedDye_.end()) {
            placed.push_back(*it);
            placedDye_.erase(it);  // two equal sources stay two
            continue;
        }
        PlacedDye p;
        p.source = s;
        p.start = dyeFrame_;
        p.posObj = methods::closestOnWholeSurface(group_, mesh, s.point);
        p.radius = s.radius > 0.0f ? s.radius : methods::kDyeRadiusPx / pixelsPerUnitAt(camera, options_.size, p.posObj);
        placed.push_back(p);
    }
    placedDye_ = std::move(placed);

    std::vector<methods::DyeEmitter> out;
    for (const PlacedDye& p : placedDye_) {
        const int f = dyeFrame_ - p.start;  // frames since the source appeared
        const int stop = p.source.stop >= 0    ? p.source.stop
                         : options_.dyeRelease > 0 ? p.source.start + options_.dyeRelease
                                                   : -1;
        if (f >= p.source.start && (stop < 0 || f < stop)) out.push_back({p.posObj, p.radius, p.source.color});
    }
    return out;
}

void Playback::stepDye(const core::Camera& camera, double time, double perFrame) {
    if (!dye_ && options_.dye.empty() && options_.dyeFileSources.empty()) return;
    const double t = surface_->unsteady() ? time : 0.0;
    const core::SurfaceMesh& mesh = surface_->meshAtTime(t);
    // The band: made at the first step, again when the geometry changes (the dye with it).
    // Split over processes (ParaView under MPI) each holds a piece and every one the whole
    // band (methods/common/dye_shared.h): made again when any piece changed.
    if (dye_ && !sameGeometryEverywhere(dye_->sameGeometry(mesh))) {
        dye_.reset();
        resetDye();
    }
    if (!dye_) {
        const methods::SurfaceGpu& s = surface_->atTime(t);
        const float h = kDyeVoxelPx / core::maxPixelsPerUnit(camera, options_.size, s.bounds());
        dye_ = std::make_unique<methods::DyeField>(mesh, surface_->field(), s.bounds(), h, group_);
        dyeVelocityTime_ = t;
        if (surface_->unsteady()) {
            dyeDt_ = perFrame;
        } else if (options_.timePerFrame > 0.0) {
            dyeDt_ = options_.timePerFrame;
        } else {
            // The fastest dye (98th percentile of the speed, as the colour map's top) moves
            // --step-px pixels per frame at this view.
            const float speed = s.colorSpeedMax() > 0.0f ? s.colorSpeedMax() : dye_->maxSpeed();
            const float pxPerUnit = core::maxPixelsPerUnit(camera, options_.size, s.bounds());
            dyeDt_ = speed > 0.0f ? options_.params.common.stepPx / (speed * pxPerUnit) : 0.0;
        }
    }
    if (surface_->unsteady()) {
        dyeDt_ = perFrame;
        if (t != dyeVelocityTime_) {  // each step's field (interpolated as the surface is)
            dye_->setVelocity(mesh, surface_->field());
            dyeVelocityTime_ = t;
        }
    }
    const std::vector<methods::DyeEmitter> emitters = dyeEmitters(camera, mesh);
    dye_->step(dyeFrame_ > 0 ? float(dyeDt_) : 0.0f, options_.dyeDecay, emitters);
    ++dyeFrame_;
}

}  // namespace flowsurf::session
