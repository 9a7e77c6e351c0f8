#include "view_pipeline.h"
#include "io/series_reader.h"

#include "core/errors.h"
#include "session/scene_setup.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace flowsurf::app::view {

namespace {

// A one-step input read once: rebuilding the renderers (every parameter change) must
// not read the file again.
class CachedStep final : public core::StepProvider {
public:
    explicit CachedStep(std::unique_ptr<core::StepProvider> inner) : inner_(std::move(inner)) {}
    size_t count() const override { return inner_->count(); }
    double time(size_t i) const override { return inner_->time(i); }
    core::SurfaceMesh load(size_t i) override {
        if (!cached_ || cachedIndex_ != i) {
            cached_ = std::make_unique<core::SurfaceMesh>(inner_->load(i));
            cachedIndex_ = i;
        }
        return *cached_;
    }
    std::string label(size_t i) const override { return inner_->label(i); }
    core::Bounds bounds() override { return load(0).bounds(); }

private:
    std::unique_ptr<core::StepProvider> inner_;
    std::unique_ptr<core::SurfaceMesh> cached_;
    size_t cachedIndex_ = 0;
};

}  // namespace

void ViewPipeline::load(const RenderOptions& o, const std::vector<methods::Method>& views) {
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, session::sourceOptions(o));
    if (steps->count() == 1) steps = std::make_unique<CachedStep>(std::move(steps));
    const core::Bounds bounds = steps->bounds();
    const core::SurfaceMesh first = steps->load(o.timeStepGiven ? o.timeStep : 0);
    std::vector<std::string> fields;
    for (const auto& f : first.fields) fields.push_back(f.name);
    // The playback checks the field and loads the first step: errors surface here, and
    // the old data and its playback stay.
    auto playback = std::make_unique<session::Playback>(o, *steps, views);
    playback->setStageTiming(true);
    playback_ = std::move(playback);
    steps_ = std::move(steps);
    lastViews_ = views;
    bounds_ = bounds;
    fields_ = std::move(fields);
    input_ = o.input;
    triangles_ = first.triangles.size();
    framebuffers();
}

void ViewPipeline::build(const RenderOptions& o, const std::vector<methods::Method>& views) {
    if (!playback_) throw ConfigError("no data loaded");
    playback_->setViews(views);
    try {
        playback_->setOptions(o);
        playback_->rebuild();
    } catch (...) {
        playback_->setViews(lastViews_);
        framebuffers();
        throw;
    }
    lastViews_ = views;
    framebuffers();
}

void ViewPipeline::framebuffers() {
    readFbos_.clear();
    for (size_t i = 0; playback_ && i < playback_->viewCount(); ++i) {
        readFbos_.push_back(gl::Framebuffer::create());
        readFbos_.back().attach(GL_COLOR_ATTACHMENT0, playback_->view(i).composite());
        glNamedFramebufferReadBuffer(readFbos_.back().id(), GL_COLOR_ATTACHMENT0);
    }
}

std::string ViewPipeline::methodName(size_t i) const {
    return std::string(methods::nameOf(methods::kMethodNames, playback_->viewMethod(i)));
}

void ViewPipeline::render(const session::Playback::LiveFrame& f, bool advance) {
    if (!playback_) return;
    playback_->render(f, advance);
    triangles_ = playback_->surface().atTime(f.time).triangleCount();
}

}  // namespace flowsurf::app::view
