#include "methods/image_work.h"

namespace flowsurf::methods {

ImageWork::ImageWork(const core::Viewport& viewport, const CommonParams& params, int historySlots)
    : viewport_(viewport), mode_(params.parallel), madeWith_(size_t(historySlots)) {}

void ImageWork::beginFrame(const FrameInput& in) {
    group_ = in.group;
    tiled_ = tiledParallel(group_, mode_);
    if (tiled_ && !tiles_) tiles_ = std::make_unique<ScreenTiles>(viewport_);
    if (tiles_) tiles_->beginFrame();
}

void ImageWork::mergeReplicated(const gl::Texture2D& depth, std::initializer_list<const gl::Texture2D*> layers) const {
    if (!tiled_ && group_) mergeByDepth(*group_, depth, layers);
}

void ImageWork::distribute(const gl::Texture2D& depth, std::span<const TileLayer> layers, int guardPx,
                           const PixelRect& footprint, gl::StageTimer& timer) {
    timer.begin(stageName(Stage::TileExchange));
    tiles_->distribute(*group_, depth, layers, guardPx, footprint);
}

PixelRect ImageWork::tile() const {
    return tiled_ ? tiles_->tile() : PixelRect{0, 0, viewport_.width, viewport_.height};
}

bool ImageWork::pull(int slot, const gl::Texture2D& texture, const PixelRect& wanted, gl::StageTimer& timer,
                     Stage resume) {
    if (!tiled_ || madeWith_[size_t(slot)].empty()) return false;
    timer.begin(stageName(Stage::TileExchange));
    tiles_->pull(*group_, texture, madeWith_[size_t(slot)], wanted);
    timer.begin(stageName(resume));
    return true;
}

void ImageWork::reportCost(float ms, float ownMs) {
    if (tiled_) tiles_->reportCost(*group_, ms, ownMs);
}

void ImageWork::made(int slot) {
    if (tiled_) madeWith_[size_t(slot)] = tiles_->tiles();
}

void ImageWork::returnValues(const gl::Texture2D& values, gl::StageTimer& timer) {
    if (!tiled_) return;
    timer.begin(stageName(Stage::TileReturn));
    tiles_->returnValues(*group_, values);
}

}  // namespace flowsurf::methods
