#include "methods/isa/isa_renderer.h"

#include "gpu/gl_path.h"
#include "methods/stages.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flowsurf::methods::isa {

IsaRenderer::IsaRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group)
    : params_(params),
      viewport_(viewport),
      // Every ISA stage reads the velocity image's colours where its depth is < 1 only.
      velocityImage_{SurfaceGBuffer(viewport, false, params.common.cullBackFaces, false, params.common.surfaceRaster),
                     SurfaceGBuffer(viewport, false, params.common.cullBackFaces, false, params.common.surfaceRaster)},
      frozenDepth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      advectionMesh_(viewport, params.isa.gridRes, resolveGlPath(params.common.glPath)),
      textureAdvection_(viewport, params.isa, params.common),
      work_(viewport, params.common, group, kDepthSlot + 3, 2),
      tail_(params.common, viewport, work_),
      motion_(params.common.onCameraMove),
      flow_(viewport),
      composite_(GL_RGBA8, viewport) {}

bool IsaRenderer::viewChanged(const FrameInput& in) const {
    return !haveCache_ || in.surface->generation() != cachedGeneration_ || !core::sameCamera(in.camera, cachedCamera_);
}

// The cached advection mesh maps into the source view and carries the frame's dt: it is
// stale when the view, the geometry or data, the source view (the translate remedy's
// previous camera: equal to the view one frame after the camera stops) or the freeze
// changed. A mesh kept from the last moving frame would go on applying that frame's
// camera motion every frame (a drift after a drag, a radial smear after a zoom).
bool IsaRenderer::meshStale(const FrameInput& in, const MotionPlan& plan) const {
    return viewChanged(in) || !core::sameCamera(plan.sourceCamera, cachedSourceCamera_) || plan.advect != cachedAdvect_;
}

// The depth of the whole surface per velocity image (where this process's stages run).
const gl::Texture2D& IsaRenderer::depthOf(int v) const { return work_.wholeDepth(v, velocityImage_[v].depth()); }

void IsaRenderer::renderFrame(const FrameInput& in) {
    timer_.beginFrame();
    work_.beginFrame();

    // Interaction remedy [L §IV-I]: which view the source texture was made in.
    const MotionPlan plan = motion_.plan(in.camera);
    if (plan.freezeStarts) {  // keep where the frozen texture was made
        glCopyImageSubData(depthOf(vi_).id(), GL_TEXTURE_2D, 0, 0, 0, 0, frozenDepth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                           viewport_.width, viewport_.height, 1);
        work_.copied(kDepthSlot + vi_, kDepthSlot + 2);
    }
    if (plan.advect || plan.freezeStarts) source_ = current_;

    // Dynamic case [L Table II]: view, geometry or data changed (and the frame after, whose
    // source view changed), or the measured costs call for a new split of the work:
    // (1) velocity image and (2) advection mesh. Static: reuse them.
    const bool resplit = work_.splitDue() && !viewChanged(in);
    lastDynamic_ = meshStale(in, plan) || resplit;
    if (lastDynamic_) updateMesh(in, plan, resplit);

    // (3) texture advection with edge blending [L §IV-D.1, §IV-E.1] and
    // (4) noise injection and blending on the surface only [L eq. 9], one pass
    advectTexture(in, plan);

    // (4b) contrast enhancement, display only [doc/contrast.md]: the advection goes on
    // from F_a itself, and (5) overlay with texture clipping and velocity mask [L eq. 10, Fig. 10]
    const SurfaceGBuffer& vel = velocityImage_[vi_];
    tail_.show(in, flow_.texture(current_), {vel.depth(), vel.shade(), vel.mask()}, composite_.fbo(), timer_);
    timer_.endFrame();
}

// The whole surface's velocity image where this process advects: replicated, all of it on
// every process; tiles, its velocity and depth over this tile plus a grid cell.
void IsaRenderer::gatherVelocity() {
    SurfaceGBuffer& v = velocityImage_[vi_];
    // The advection mesh reads the velocity where the whole surface's depth is < 1 only: this
    // piece's own stands for the background (the velocity image does not clear it), and the
    // tile's merge goes into it (the overlay reads this piece's depth, shade and mask, not its
    // velocity).
    const TileLayer tileLayers[] = {TileLayer::of(v.velocity(), v.velocity(), 0.0f, true),
                                    TileLayer::of(v.depth(), depthOf(vi_))};
    work_.gather(v, tileLayers, guardPx(), timer_);
    work_.made(kDepthSlot + vi_);
}

// Stages (1) and (2) of the dynamic case; `resplit`: the view is the same, only the work is
// split again (from the same velocity image).
void IsaRenderer::updateMesh(const FrameInput& in, const MotionPlan& plan, bool resplit) {
    const CommonParams& c = params_.common;
    const int prevVi = vi_;
    const bool newView = viewChanged(in);
    if (newView) {
        vi_ = 1 - vi_;
        // (1) velocity image: mesh with per-vertex velocity, nearest layer [L §IV-C.1]
        timer_.begin(stageName(Stage::VelocityImage));
        velocityImage_[vi_].render(*in.surface, in.camera, work_.occluders());
    }
    if (newView || resplit) gatherVelocity();

    // (2) advection mesh + edge detection [L §IV-D.1, eq. 12, eq. 14]
    timer_.begin(stageName(Stage::AdvectionMesh));
    const bool sameView = core::sameCamera(plan.sourceCamera, in.camera);
    const int sourceVi = !plan.advect ? 2 : sameView ? vi_ : prevVi;  // 2: the frozen depth
    const gl::Texture2D& sourceDepth = sourceVi == 2 ? frozenDepth_ : depthOf(sourceVi);
    // Tiles: the vertices this tile's pixels interpolate, the only ones it reads.
    const std::optional<PixelRect> tile = work_.tileOnly();
    const std::optional<PixelRect> vertices = tile ? std::optional(meshVertices(*tile)) : std::nullopt;
    const float dt = plan.advect ? dtForStep(in, viewport_, c.stepPx, work_.group()) : 0.0f;
    const auto computeMesh = [&] {
        advectionMesh_.compute(velocityImage_[vi_].velocity(), depthOf(vi_), sourceDepth, in.camera,
                               plan.sourceCamera, dt, params_.isa.edgeEpsilon, vertices);
    };
    computeMesh();
    if (tile) {
        // The edge test reads the source depth where the flow came from: the mesh's
        // footprint, known once it is computed (its coordinates do not depend on that
        // depth); that part of the depth from its makers, then the mesh again.
        footprint_ = footprint(*tile);
        if (work_.pull(kDepthSlot + sourceVi, sourceDepth, footprint_, timer_, Stage::AdvectionMesh)) computeMesh();
    }
    haveCache_ = true;
    cachedGeneration_ = in.surface->generation();
    cachedCamera_ = in.camera;
    cachedSourceCamera_ = plan.sourceCamera;
    cachedAdvect_ = plan.advect;
}

// Stages (3) and (4): F_a(k) from F_a(k-1) through the advection mesh, with the noise.
// Tiles: on this tile only, the source from its makers; the result returned to the
// processes whose pieces cover each pixel.
void IsaRenderer::advectTexture(const FrameInput& in, const MotionPlan& plan) {
    const CommonParams& c = params_.common;
    const int target = 1 - source_;
    timer_.begin(stageName(Stage::TextureAdvection));
    const NoiseStep noise{in.frame, plan.advect ? c.alpha : 0.0f, c.noise};
    work_.pull(source_, flow_.texture(source_), footprint_, timer_, Stage::TextureAdvection);
    const auto advected = ImageWork::Clock::now();
    if (!work_.tile().empty())
        textureAdvection_.apply(advectionMesh_.vertices(), flow_.texture(source_), depthOf(vi_), flow_.texture(target),
                                flow_.fbo(target), params_.isa.edgeBlending, noise,
                                work_.tileOnly().value_or(PixelRect{}));
    current_ = target;
    // Tiles: the tile's cost; the owners keep their tiles of F_a for the next frame's pulls;
    // (4b) the contrast histogram of this tile, summed over the processes; F_a at this
    // piece's own pixels (what its overlay shows) from their tiles' owners.
    work_.finished(advected);
    work_.made(target);
    tail_.measureTile(flow_.texture(target), depthOf(vi_), timer_);
    work_.returnValues(flow_.texture(target), timer_);
}

// The advection mesh's vertices [x0, x1) x [y0, y1) that the pixels of `tile` interpolate.
PixelRect IsaRenderer::meshVertices(const PixelRect& tile) const {
    if (tile.empty()) return {};
    const int r = params_.isa.gridRes, w = viewport_.width, h = viewport_.height;
    return {std::clamp(tile.x0 * r / w, 0, r), std::clamp(tile.y0 * r / h, 0, r),
            std::clamp((tile.x1 * r + w - 1) / w + 1, 0, r) + 1, std::clamp((tile.y1 * r + h - 1) / h + 1, 0, r) + 1};
}

// Where the pixels of `tile` read the source F_a: the box of the advection mesh's source
// coordinates over the vertices the tile's pixels interpolate, plus the bicubic's reach.
PixelRect IsaRenderer::footprint(const PixelRect& tile) const {
    const PixelRect m = meshVertices(tile);
    if (m.empty()) return {};
    const int w = viewport_.width, h = viewport_.height;
    std::vector<glm::vec4> v(m.area());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(advectionMesh_.vertices().id(), 0, m.x0, m.y0, 0, m.width(), m.height(), 1, GL_RGBA, GL_FLOAT,
                         GLsizei(v.size() * sizeof(glm::vec4)), v.data());
    glm::vec2 lo{float(w), float(h)}, hi{0.0f, 0.0f};
    for (const glm::vec4& p : v) {
        const glm::vec2 px = glm::vec2(p) * glm::vec2(float(w), float(h));
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
    }
    constexpr int kReach = 3;  // the bicubic's 4 x 4 texels around a coordinate, and rounding
    return PixelRect{int(std::floor(lo.x)) - kReach, int(std::floor(lo.y)) - kReach, int(std::ceil(hi.x)) + kReach,
                     int(std::ceil(hi.y)) + kReach}
        .intersect({0, 0, w, h});
}

// How far beyond its tile a process reads the velocity image: the per-pixel warp
// interpolates the advection mesh's four vertices around each pixel, and a vertex reads the
// texel under it: one grid cell and a pixel.
int IsaRenderer::guardPx() const {
    const int cell = (std::max(viewport_.width, viewport_.height) + params_.isa.gridRes - 1) / params_.isa.gridRes;
    return cell + 2;
}

}  // namespace flowsurf::methods::isa
