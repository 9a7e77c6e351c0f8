#include <flowsurf/renderer.h>

#include "api/surface_data.h"
#include "core/errors.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "session/options/dye_sources.h"
#include "session/options/options.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <iterator>
#include <mutex>

namespace flowsurf {

namespace {

// Headless contexts are made current on whichever thread calls; one call at a time.
std::recursive_mutex& glMutex() {
    static std::recursive_mutex m;
    return m;
}

}  // namespace

struct Renderer::Impl {
    ContextMode mode = ContextMode::Own;
    std::unique_ptr<gl::HeadlessContext> context;
    // The frame loop of the command line and the one owner of the options; open while a
    // surface is (after render or begin). Declared after the steps it reads: goes first.
    std::shared_ptr<const detail::SurfaceData> data;
    std::unique_ptr<core::StepProvider> steps;
    session::Playback playback;
    int qualityEvery = 0;  // of the next render or begin

    Impl() { playback.setStageTiming(true); }

    // Holds the lock and the context for one public call.
    struct Scope {
        std::unique_lock<std::recursive_mutex> lock;
        Impl& impl;
        explicit Scope(Impl& i) : lock(glMutex()), impl(i) {
            if (impl.context) impl.context->makeCurrent();
        }
        ~Scope() {
            if (impl.context && lock.owns_lock()) impl.context->release();
        }
    };

    void open(std::shared_ptr<const detail::SurfaceData> d) {
        // Release the old stream before the new one starts (its prefetch thread reads).
        playback.close();
        steps.reset();
        data = std::move(d);
        session::RenderOptions o = playback.options();
        o.input = data->source;
        o.field = data->field;
        playback.setOptions(o);  // closed: the input's options too
        session::validateRenderOptions(o);
        steps = data->provider();
        playback.quality().configure(qualityEvery);
        playback.open(*steps);
    }

    const methods::FlowMethod& rendered() const {
        if (playback.frame() == 0) throw ConfigError("nothing rendered yet: call render() or advance() first");
        return *playback.views()[0];
    }
};

namespace {

QualityMetrics toPublic(const quality::FrameQuality& q) {
    QualityMetrics m;
    m.orientationErrorDeg = q.orientationErrorDeg;
    m.orientationErrorP90Deg = q.orientationErrorP90Deg;
    m.countedFraction = q.countedFraction;
    m.frameCorrelation = q.frameCorrelation;
    m.frameCorrelationReprojected = q.frameCorrelationReprojected;
    m.contrast = q.contrast;
    m.edgeContrastRatio = q.edgeContrastRatio;
    m.frequencyPx = q.frequencyPx;
    static_assert(sizeof(QualityMetrics) == std::tuple_size_v<std::decay_t<decltype(quality::metricTable())>> * sizeof(double),
                  "QualityMetrics holds every metric of the table, in its order");
    return m;
}

}  // namespace

std::vector<std::pair<std::string, double>> QualityMetrics::named() const {
    // Field i of QualityMetrics is metric i of the table (same order, all doubles).
    const double* values = &orientationErrorDeg;
    std::vector<std::pair<std::string, double>> out;
    for (size_t i = 0; i < quality::metricTable().size(); ++i) out.emplace_back(quality::metricTable()[i].name, values[i]);
    return out;
}

Renderer::Renderer(ContextMode mode) : impl_(std::make_unique<Impl>()) {
    std::lock_guard<std::recursive_mutex> lock(glMutex());
    impl_->mode = mode;
    if (mode == ContextMode::Own) {
        impl_->context = std::make_unique<gl::HeadlessContext>();
        impl_->context->release();
    }
}

Renderer::~Renderer() {
    if (!impl_) return;
    Impl::Scope scope(*impl_);
    impl_->playback.close();  // GL objects go while the context is current
}

Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::set(const std::string& option, const std::string& value) {
    // What the table says a change means: the input's options belong to the Surface, the
    // command line's output files to the command line; the rest the frame loop applies.
    const session::OptionEffect effect = session::effectOf(option);
    if (effect == session::OptionEffect::Reload)
        throw ConfigError("'" + option + "' is read with the surface: use Surface::read(path, field, {{\"" + option +
                          "\", value}}) or Surface::setField");
    if (effect == session::OptionEffect::Output)
        throw ConfigError("'" + option + "' is an output file setting of the command line; a Renderer returns its "
                          "images (readImage, readFlowTexture)");
    impl_->playback.set(option, value);
}

void Renderer::addDye(const std::array<float, 3>& point, float radius, const std::string& color) {
    std::vector<methods::DyeSource> sources = impl_->playback.options().dye;
    sources.push_back(session::dyeSource({point[0], point[1], point[2]}, radius,
                                         color.empty() ? std::nullopt : std::optional<std::string>(color),
                                         sources.size(), "addDye"));
    set("dye", session::dyeSourcesText(sources));
}

std::string Renderer::get(const std::string& option) const {
    const session::OptionSpec* spec = session::findOption(option);
    if (!spec) throw ConfigError("unknown option '" + option + "'");
    return spec->get(impl_->playback.options());
}

std::vector<std::string> Renderer::optionNames() {
    std::vector<std::string> names;
    for (const auto& spec : session::renderOptionTable())
        if (spec.takes(session::FrontEnd::Renderer)) names.push_back(spec.name);
    return names;
}

namespace {

// The rows of the option table that `frontEnd` takes, described.
std::vector<OptionInfo> describeOptions(session::FrontEnd frontEnd) {
    static constexpr const char* kKinds[] = {"flag", "int", "float", "text", "choice", "size", "vec3", "color", "path"};
    static_assert(std::size(kKinds) == session::kOptionKinds, "one name per OptionKind");
    std::vector<OptionInfo> out;
    for (const auto& spec : session::renderOptionTable()) {
        if (!spec.takes(frontEnd)) continue;
        std::vector<std::string> applies;
        for (const auto& [m, name] : methods::kMethodNames)
            if (spec.appliesTo(m)) applies.emplace_back(name);
        out.push_back({spec.name, session::groupName(spec.role.group), spec.help, kKinds[int(spec.kind)], spec.min,
                       spec.max, spec.choices, session::defaultText(spec), spec.arraySeparator, std::move(applies)});
    }
    return out;
}

}  // namespace

std::vector<OptionInfo> Renderer::optionInfo() { return describeOptions(session::FrontEnd::Renderer); }
std::vector<OptionInfo> Renderer::readOptionInfo() { return describeOptions(session::FrontEnd::Read); }

void Renderer::setCamera(const CameraView& v) {
    session::RenderOptions o = impl_->playback.options();
    o.eye = glm::vec3(v.eye[0], v.eye[1], v.eye[2]);
    o.target = glm::vec3(v.target[0], v.target[1], v.target[2]);
    o.up = glm::vec3(v.up[0], v.up[1], v.up[2]);
    if (glm::length(*o.up) == 0.0f) throw ConfigError("camera: the up vector must not be zero");
    if (glm::length(*o.eye - *o.target) == 0.0f) throw ConfigError("camera: eye and target must differ");
    if (!(v.fovDeg >= 1.0f && v.fovDeg <= 170.0f)) throw ConfigError("camera: fov must be 1..170 degrees");
    o.fov = v.fovDeg;
    o.ortho = std::max(0.0f, v.orthoHeight);
    impl_->playback.setOptions(o);
}

void Renderer::fitCamera() {
    session::RenderOptions o = impl_->playback.options();
    o.eye.reset();
    o.target.reset();
    o.up.reset();
    impl_->playback.setOptions(o);
}

CameraView Renderer::camera() const {
    CameraView v;
    const core::Camera c = impl_->playback.lastFrame().camera;
    for (int a = 0; a < 3; ++a) v.eye[a] = c.eye[a], v.target[a] = c.target[a], v.up[a] = c.up[a];
    v.fovDeg = c.fovDeg;
    v.orthoHeight = c.orthoHeight;
    return v;
}

void Renderer::render(const Surface& surface, int frames) {
    if (frames < 0) throw ConfigError("render: frames must not be negative");
    Impl::Scope scope(*impl_);
    impl_->open(surface.data_shared());
    impl_->playback.still(frames);
}

void Renderer::begin(const Surface& surface) {
    Impl::Scope scope(*impl_);
    impl_->open(surface.data_shared());
    impl_->playback.start(true);  // converged from frame 0, as the command line's movies
}

void Renderer::advance() {
    Impl::Scope scope(*impl_);
    session::Playback& p = impl_->playback;
    if (!p.isOpen()) throw ConfigError("advance: call begin(surface) or render(surface, frames) first");
    for (const auto& m : p.views()) m->timer().reset();
    p.advance();
}

int Renderer::frame() const { return impl_->playback.frame(); }
double Renderer::time() const { return impl_->playback.lastFrame().time; }
int Renderer::width() const { return impl_->playback.options().size.width; }
int Renderer::height() const { return impl_->playback.options().size.height; }

void Renderer::readImage(uint8_t* rgb) const {
    Impl::Scope scope(*impl_);
    std::vector<uint8_t> img = gl::readRgb8TopDown(impl_->rendered().composite());
    std::copy(img.begin(), img.end(), rgb);
}

void Renderer::readFlowTexture(float* values) const {
    Impl::Scope scope(*impl_);
    const gl::Texture2D& t = impl_->rendered().flowTexture();
    std::vector<float> bottomUp = gl::readChannel(t, 0);
    const int w = t.width(), h = t.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            values[size_t(y) * w + x] = std::clamp(bottomUp[size_t(h - 1 - y) * w + x], 0.0f, 1.0f);
}

void Renderer::readFlowTexture16(uint16_t* values) const {
    Impl::Scope scope(*impl_);
    std::vector<uint16_t> img = gl::readGray16TopDown(impl_->rendered().flowTexture());
    std::copy(img.begin(), img.end(), values);
}

std::vector<std::pair<std::string, double>> Renderer::stageMs() const {
    if (!impl_->playback.isOpen()) return {};
    Impl::Scope scope(*impl_);  // the timer reads its GPU queries
    return impl_->playback.views()[0]->timer().meanMs();
}

void Renderer::setQualityEvery(int every) {
    if (every < 0) throw ConfigError("quality: measure every N frames, N >= 0 (0: off)");
    impl_->qualityEvery = every;
}

Quality Renderer::quality() const {
    Impl::Scope scope(*impl_);
    impl_->rendered();  // throws before anything is rendered
    session::Playback& p = impl_->playback;
    Quality q;
    if (p.quality().frames(0).empty()) {
        const session::Playback::Drawn& last = p.lastFrame();
        const quality::FrameQuality now =
            p.quality().measure(0, *p.views()[0], p.surface().atTime(last.time), last.camera, last.clock);
        q.frames = 1;
        q.median = q.worst = toPublic(now);
        return q;
    }
    const quality::QualitySummary s = p.quality().summary(0);
    q.frames = s.frames;
    q.median = toPublic(s.median);
    q.worst = toPublic(s.worst);
    return q;
}

std::string Renderer::glRenderer() const {
    Impl::Scope scope(*impl_);
    return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

}  // namespace flowsurf
