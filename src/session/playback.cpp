// Index: steps · build and options · animation (start, advance, still) · live frames · results.
#include "session/playback.h"

#include "core/errors.h"
#include "gl/readback.h"
#include "methods/make_renderer.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::session {

Playback::Playback(const RenderOptions& o, std::vector<methods::Method> views, methods::ProcessGroup* group)
    : options_(o), group_(group), requestedViews_(std::move(views)), dye_(group) {}

Playback::~Playback() = default;

// --- steps -----------------------------------------------------------------------------------

void Playback::open(core::StepProvider& steps) {
    close();
    steps_ = &steps;
    try {
        build();
    } catch (...) {
        close();
        throw;
    }
    built_ = options_;
    builtViews_ = requestedViews_;
}

void Playback::reopen(core::StepProvider& steps, const RenderOptions& o) {
    FLOWSURF_CHECK(&steps != steps_);
    if (!isOpen()) {
        const RenderOptions before = options_;
        options_ = o;
        try {
            open(steps);
        } catch (...) {
            options_ = before;
            throw;
        }
        return;
    }
    // The new surface and renderers beside the open ones: a failure leaves those untouched.
    Parts parts = make(o, steps);
    close();
    options_ = o;
    steps_ = &steps;
    install(std::move(parts));
    built_ = options_;
    builtViews_ = requestedViews_;
}

void Playback::close() {
    // What a new playback would start with; options, views, timing and quality settings stay.
    methods_.clear();
    topology_.reset();
    surface_.reset();
    cameras_.reset();
    quality_.rebuilt(0, options_.size, options_.params.common.cullBackFaces);
    dye_ = DyeInjection(group_);
    steps_ = nullptr;
    rebuildPending_ = camerasPending_ = false;
    started_ = startWarm_ = false;
    frame_ = warmedUp_ = 0;
    clock_ = 0;
    last_ = Drawn{};
}

void Playback::requireOpen(const char* call) const {
    if (!steps_) throw ConfigError(std::string(call) + ": no steps are open");
}

// --- build and options -------------------------------------------------------------------

std::vector<methods::Method> Playback::shownViews(const std::vector<methods::Method>& views, const RenderOptions& o) {
    return views.empty() ? std::vector<methods::Method>{o.method} : views;
}

Playback::Parts Playback::make(const RenderOptions& o, core::StepProvider& steps) const {
    Parts parts;
    parts.surface = std::make_unique<AnimatedSurface>(o, steps, group_);
    const methods::MethodParams params = parts.surface->paramsFor(o.params);
    for (methods::Method m : shownViews(requestedViews_, o))
        parts.methods.push_back(methods::makeRenderer(m, params, o.size, group_));
    for (auto& m : parts.methods) m->timer().setEnabled(stageTiming_);
    if (o.topology) {
        // The overlay analyses the surface it is given: in a group that is one piece. ParaView's
        // representation gathers the pieces and draws its own (mapper_topology.h).
        if (group_)
            throw ConfigError("--topology on: not drawn by a parallel frame loop (each process holds a piece); "
                              "analyse the whole surface and draw it after the frame, as ParaView's "
                              "FlowSurfTopology does");
        parts.topology = std::make_unique<TopologyOverlay>(steps, o);
    }
    return parts;
}

void Playback::build() {
    // One surface streams from the steps at a time (its prefetch thread reads them).
    methods_.clear();
    topology_.reset();
    surface_.reset();
    cameras_.reset();
    install(make(options_, *steps_));
}

void Playback::install(Parts parts) {
    cameras_.reset();
    dye_.dropBand();
    dye_.restart();
    surface_ = std::move(parts.surface);
    methods_ = std::move(parts.methods);
    topology_ = std::move(parts.topology);
    last_.topology = nullptr;  // the old overlay's, gone with it
    rebuildPending_ = camerasPending_ = false;
    clock_ = 0;
    warmedUp_ = 0;
    quality_.rebuilt(methods_.size(), options_.size, options_.params.common.cullBackFaces);
}

void Playback::rebuild() {
    requireOpen("rebuild");
    try {
        build();
    } catch (...) {
        // The options and methods of the last build that worked, again.
        options_ = built_;
        requestedViews_ = builtViews_;
        build();
        throw;
    }
    built_ = options_;
    builtViews_ = requestedViews_;
}

bool Playback::applyPending() {
    requireOpen("render");
    const bool rebuilt = rebuildPending_;
    if (rebuildPending_) rebuild();
    if (camerasPending_) {
        cameras_.reset();
        camerasPending_ = false;
    }
    return rebuilt;
}

OptionEffect Playback::set(const std::string& name, const std::string& value) {
    const OptionEffect effect = effectOf(name);
    if (effect == OptionEffect::Reload && isOpen())
        throw ConfigError("--" + name + " is read with the input: open the input again to change it");
    setOption(options_, name, value);
    if (effect == OptionEffect::Camera) camerasPending_ = true;
    if (effect == OptionEffect::Rebuild) rebuildPending_ = true;
    return effect;
}

OptionEffect Playback::setOptions(const RenderOptions& o) {
    const OptionEffect effect = changeEffect(options_, o);
    if (effect == OptionEffect::Reload && isOpen())
        throw ConfigError("the input's options changed (input, field, patches...): open the input again");
    options_ = o;
    if (effect == OptionEffect::Camera) camerasPending_ = true;
    if (effect == OptionEffect::Rebuild) rebuildPending_ = true;
    return effect;
}

void Playback::setViews(std::vector<methods::Method> views) {
    requestedViews_ = std::move(views);
    if (shownViews(requestedViews_, options_) != shownViews(builtViews_, built_)) rebuildPending_ = true;
}

void Playback::setStageTiming(bool on) {
    stageTiming_ = on;
    for (auto& m : methods_) m->timer().setEnabled(on);
}

void Playback::stepsChanged() {
    requireOpen("stepsChanged");
    dye_.dropBand();  // the geometry may have changed: the band is made again at the next step
    surface_.reset();
    surface_ = std::make_unique<AnimatedSurface>(options_, *steps_, group_);
}

// --- an animation --------------------------------------------------------------------------

const FrameCameras& Playback::frameCameras() {
    if (!cameras_) cameras_ = std::make_unique<FrameCameras>(options_, steps_->bounds());
    return *cameras_;
}

void Playback::restart() {
    frame_ = 0;
    clock_ = 0;
    warmedUp_ = 0;
    quality_.clear();
    dye_.restart();
    if (startWarm_) {
        const core::Camera camera = frameCameras().at(0);
        const double t = surface_->unsteady() ? surface_->timeAt(0) : 0.0;
        warmUp({camera, t, surface_->mapping().perFrame});
    }
}

void Playback::start(bool warmUp) {
    requireOpen("start");
    started_ = true;
    startWarm_ = warmUp;
    applyPending();
    restart();
}

void Playback::animationFrame(int f, uint32_t k) {
    const double t = surface_->unsteady() ? surface_->timeAt(f) : 0.0;
    dye_.step(options_, *surface_, frameCameras().at(f), t, surface_->mapping().perFrame);
    renderAll(frameCameras().at(f), t, surface_->mapping().perFrame, k);
}

void Playback::advance() {
    if (!started_) throw ConfigError("advance: the animation has not started");
    if (applyPending()) restart();  // an option asked for new renderers: the animation starts over
    quality_.planFrame();
    animationFrame(frame_, uint32_t(warmedUp_ + frame_));
    ++frame_;
    clock_ = uint32_t(warmedUp_ + frame_);
}

void Playback::still(int f) {
    requireOpen("still");
    started_ = true;
    startWarm_ = false;
    applyPending();
    restart();
    // A history-free method's frame f needs no frame before it (the dye and the quality's
    // frame before f do).
    for (int k = 0; k <= f; ++k) {
        quality_.planStill(f, k);
        if (k < f && historyFree() && !quality_.plannedFrame()) {
            const double t = surface_->unsteady() ? surface_->timeAt(k) : 0.0;
            dye_.step(options_, *surface_, frameCameras().at(k), t, surface_->mapping().perFrame);
            continue;
        }
        animationFrame(k, uint32_t(k));
    }
    frame_ = f + 1;
    clock_ = uint32_t(f + 1);
}

// --- live frames ---------------------------------------------------------------------------

void Playback::warmUp(const LiveFrame& at) {
    applyPending();
    const int w = warmupFrames();
    quality_.planNothing();
    for (int k = 0; k < w; ++k) renderAll(at.camera, at.time, at.perFrame, uint32_t(k));
    warmedUp_ = w;
    clock_ = uint32_t(w);
}

void Playback::render(const LiveFrame& f, bool advance) {
    applyPending();
    quality_.planFrame();
    if (advance) dye_.step(options_, *surface_, f.camera, f.time, f.perFrame);
    renderAll(f.camera, f.time, f.perFrame, clock_);
    if (advance) ++clock_;
}

void Playback::renderAll(const core::Camera& camera, double time, double perFrame, uint32_t k) {
    const methods::SurfaceGpu& s = surface_->atTime(time);
    const methods::TimeLevels* levels = nullptr;
    bool levelsRead = false;
    quality_.frameStarts();
    for (size_t i = 0; i < methods_.size(); ++i) {
        methods::FlowMethod* m = methods_[i].get();
        if (m->usesTimeLevels() && !levelsRead) {
            levels = surface_->levelsAtTime(time, perFrame);
            levelsRead = true;
        }
        methods::FrameInput in{&s, camera, k, m->usesTimeLevels() ? levels : nullptr};
        in.dye = dye_.view(camera, options_.size);
        m->renderFrame(in);
        if (quality_.plannedFrame()) quality_.collect(i, *m, s, camera, k);
        if (topology_) topology_->draw(*m, camera, time);
    }
    quality_.frameDone();
    last_ = {camera, surface_->unsteady() ? time : 0.0, k, int(k) - warmedUp_,
             topology_ ? &topology_->current() : nullptr};
    if (onFrame_) onFrame_();
}

// --- results -------------------------------------------------------------------------------

bool Playback::historyFree() const {
    return std::all_of(methods_.begin(), methods_.end(), [](const auto& m) { return m->historyFree(); });
}

int Playback::warmupFrames() const {
    if (options_.warmup >= 0) return options_.warmup;
    if (historyFree()) return 0;
    return int(std::ceil(3.0f / std::max(options_.params.common.alpha, 1e-3f)));
}

std::vector<uint8_t> Playback::readImage(int* width, int* height) const {
    const int n = int(methods_.size());
    const core::Viewport v = options_.size;
    *width = n * v.width;
    *height = v.height;
    std::vector<uint8_t> out(size_t(*width) * size_t(*height) * 3);
    for (int i = 0; i < n; ++i) {
        std::vector<uint8_t> img = gl::readRgb8TopDown(methods_[size_t(i)]->composite());
        for (int y = 0; y < v.height; ++y)
            std::copy_n(&img[size_t(y) * v.width * 3], size_t(v.width) * 3,
                        &out[(size_t(y) * size_t(*width) + size_t(i) * v.width) * 3]);
    }
    return out;
}

}  // namespace flowsurf::session
