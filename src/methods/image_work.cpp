#include "methods/image_work.h"

#include "core/errors.h"
#include "parallel/screen_split.h"
#include "raster/surface_gbuffer.h"
#include "raster/surface_gpu.h"

#include <string>

namespace flowsurf::methods {

namespace {
ImageWork::Mode modeOf(const ProcessGroup* group, ParallelMode parallel) {
    if (!group) return ImageWork::Mode::Whole;
    return group->size() > 1 && parallel == ParallelMode::Tiles ? ImageWork::Mode::Tiled : ImageWork::Mode::Replicated;
}
}  // namespace

ImageWork::ImageWork(const core::Viewport& viewport, const CommonParams& params, ProcessGroup* group, int historySlots,
                     int depthTargets)
    : viewport_(viewport), group_(group), mode_(modeOf(group, params.parallel)), madeWith_(size_t(historySlots)) {
    // The colour's percentiles need the whole image's colours, made from each process's own shade.
    if (enhancesColor(params.enhanceContrast) && tiled())
        throw ConfigError("enhance-contrast " + std::string(nameOf(kEnhanceContrastNames, params.enhanceContrast)) +
                          ": the colour's stretch needs the whole image's colours, which the tiles mode divides "
                          "over the processes; set parallel to replicate (FlowSurfParallel) or enhance-contrast to "
                          "texture");
    if (!tiled()) return;
    tiles_ = std::make_unique<ScreenTiles>(viewport);
    for (int i = 0; i < depthTargets; ++i)
        wholeDepth_.emplace_back(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST);
}

void ImageWork::beginFrame() {
    if (tiles_) tiles_->beginFrame();
}

void ImageWork::gather(SurfaceGBuffer& buffers, std::span<const TileLayer> tileLayers, int guardPx,
                       gl::StageTimer& timer) {
    if (mode_ == Mode::Replicated) buffers.merge(*group_);
    if (!tiled()) return;
    distribute(buffers.depth(), tileLayers, guardPx, buffers.footprint(), timer);
    if (buffers.clearsBackground()) buffers.overwritten(tiles_->written());
}

void ImageWork::gather(const gl::Texture2D& depth, const PixelRect& footprint,
                       std::initializer_list<const gl::Texture2D*> whole, std::span<const TileLayer> tileLayers,
                       int guardPx, gl::StageTimer& timer) {
    if (mode_ == Mode::Replicated) mergeByDepth(*group_, depth, whole);
    if (tiled()) distribute(depth, tileLayers, guardPx, footprint, timer);
}

void ImageWork::distribute(const gl::Texture2D& depth, std::span<const TileLayer> layers, int guardPx,
                           const PixelRect& footprint, gl::StageTimer& timer) {
    timer.begin(stageName(Stage::TileExchange));
    tiles_->distribute(*group_, depth, layers, guardPx, footprint);
}

const gl::Texture2D& ImageWork::wholeDepth(int i, const gl::Texture2D& own) const {
    return i < int(wholeDepth_.size()) ? wholeDepth_[size_t(i)] : own;
}

PixelRect ImageWork::tile() const {
    return tiled() ? tiles_->tile() : PixelRect{0, 0, viewport_.width, viewport_.height};
}

std::optional<PixelRect> ImageWork::tileOnly() const {
    if (!tiled()) return std::nullopt;
    return tiles_->tile();
}

std::optional<PixelRect> ImageWork::piecePixels(const SurfaceGpu& surface, const core::Camera& camera) const {
    if (!tiled()) return std::nullopt;
    return projectedRect(surface.pieceParts(), camera.viewProjection(viewport_.aspect()), viewport_.width,
                         viewport_.height);
}

bool ImageWork::pull(int slot, const gl::Texture2D& texture, const PixelRect& wanted, gl::StageTimer& timer,
                     Stage resume) {
    if (!tiled() || madeWith_[size_t(slot)].empty()) return false;
    timer.begin(stageName(Stage::TileExchange));
    tiles_->pull(*group_, texture, madeWith_[size_t(slot)], wanted);
    timer.begin(stageName(resume));
    return true;
}

float ImageWork::costSince(Clock::time_point start) const { return tiled() ? ScreenTiles::finishedMs(start) : 0.0f; }

void ImageWork::finished(Clock::time_point start, float ownMs) {
    if (tiled()) tiles_->reportCost(*group_, ScreenTiles::finishedMs(start), ownMs);
}

void ImageWork::made(int slot) {
    if (tiled()) madeWith_[size_t(slot)] = tiles_->tiles();
}

void ImageWork::returnValues(const gl::Texture2D& values, gl::StageTimer& timer) {
    if (!tiled()) return;
    timer.begin(stageName(Stage::TileReturn));
    tiles_->returnValues(*group_, values);
}

}  // namespace flowsurf::methods
