#include "view_state.h"

#include "core/errors.h"
#include "session/scene_setup.h"


#include <algorithm>
#include <cstdlib>
#include <cmath>

namespace flowsurf::app::view {

const std::vector<KeyBinding>& keyTable() {
    static const std::string nextMethod = "next method (" + methods::nameList(methods::kMethodNames) + ")";
    static const std::vector<KeyBinding> keys = {
        {"r", "reset the view (fit the bounds)"},
        {"x", "view along +x (X: along -x)"},
        {"y", "view along +y (Y: along -y)"},
        {"z", "view along +z (Z: along -z)"},
        {"space", "pause / resume the animation"},
        {"n", "single step (one frame while paused)"},
        {"m", nextMethod.c_str()},
        {"c", "side by side: all three methods / one"},
        {"t", "rotation: turntable / trackball"},
        {"left", "previous time step (series)"},
        {"right", "next time step (series)"},
        {"l", "loop the time series on / off"},
        {"h", "show / hide the panel (also f1)"},
        {"p", "screenshot (PNG of the image, no panel)"},
        {"v", "start / stop recording MP4"},
        {"s", "save settings (JSON config for render --config)"},
        {"k", "append the camera to a --camera-path file"},
        {"q", "quit (also escape)"},
    };
    return keys;
}

namespace {

bool parseBool(const std::string& name, const std::string& v) {
    if (v == "true" || v == "on" || v == "1") return true;
    if (v == "false" || v == "off" || v == "0") return false;
    throw ConfigError(name + ": '" + v + "' is not true or false");
}

}  // namespace

ViewerState::ViewerState(const RenderOptions& o)
    : playback_(std::make_unique<session::Playback>(o)), window_(o.size) {
    if (o.up) turntableUp_ = glm::normalize(*o.up);
    playback_->setStageTiming(true);  // the panel shows each stage's time
}

void ViewerState::setWindowSize(int width, int height) {
    const core::Viewport before = window_;
    window_ = {std::max(width, 16), std::max(height, 16)};
    // A camera the viewer fitted (not one the user moved) fits the new area: the panel
    // collapsed or shown again, the window resized [doc/contrast.md, the viewer's framing].
    if (fitted_ && haveData_ && (window_.width != before.width || window_.height != before.height)) fit();
}

void ViewerState::fit() {
    RenderOptions o = options();
    o.eye.reset();
    o.target.reset();
    o.up = turntableUp_;
    o.size = viewSize();
    setCamera(makeCamera(o, bounds_));
    fitted_ = true;
}

std::vector<methods::Method> ViewerState::shownMethods() const {
    return compare.empty() ? std::vector<methods::Method>{options().method} : compare;
}

core::Viewport ViewerState::viewSize() const {
    const int n = int(shownMethods().size());
    return {std::max(16, window_.width / n), window_.height};
}

void ViewerState::dataLoaded(const core::Bounds& bounds, const std::vector<double>& times,
                             const core::TimeMapping& mapping) {
    bounds_ = bounds;
    haveData_ = true;
    // Fitted: no camera given (a reload keeps the fitted camera's eye, and its fit).
    const bool fitted = fitted_ || (!options().eye && !options().target);
    fitted_ = false;
    if (options().orbit == 0.0f && options().cameraPath.empty()) {
        RenderOptions fit = options();
        fit.size = viewSize();
        setCamera(makeCamera(fit, bounds_));
        fitted_ = fitted;
    }
    setTimes(times, mapping);
}

void ViewerState::setTimes(const std::vector<double>& times, const core::TimeMapping& mapping) {
    stepTimes = times;
    if (!times.empty()) {
        timeStart = mapping.start;
        timeEnd = mapping.end;
        timePerFrame = mapping.perFrame;
        time = timeStart;
    }
}

core::Camera ViewerState::camera() const {
    RenderOptions o = options();
    o.size = viewSize();
    if (!haveData_) return core::Camera{};
    if (o.orbit != 0.0f || !o.cameraPath.empty()) return FrameCameras(o, bounds_).at(int(playback_->clock()));
    return makeCamera(o, bounds_);
}

void ViewerState::setCamera(const core::Camera& c) {
    edit([&](RenderOptions& o) {
        o.eye = c.eye;
        o.target = c.target;
        o.up = glm::normalize(c.up);
        o.fov = c.fovDeg;
        o.ortho = c.orthoHeight;
    });
}

void ViewerState::takeOverCamera() {
    fitted_ = false;  // the user's camera from now on
    if (!haveData_) return;
    if (options().orbit != 0.0f || !options().cameraPath.empty()) {
        const core::Camera c = camera();
        edit([](RenderOptions& o) {
            o.orbit = 0.0f;
            o.cameraPath.clear();
        });
        setCamera(c);
    }
}

void ViewerState::dropCameraPath() {
    edit([](RenderOptions& o) { o.cameraPath.clear(); });
}

void ViewerState::frameDone() {
    if (!advancing()) return;
    stepOnce = false;
    if (timePlaying && !stepTimes.empty() && timePerFrame != 0.0) {
        time += timePerFrame;
        const double lo = std::min(timeStart, timeEnd), hi = std::max(timeStart, timeEnd);
        if (time > hi || time < lo) time = loop ? timeStart : std::clamp(time, lo, hi);
    }
}

void ViewerState::resetView() {
    if (!haveData_) return;
    takeOverCamera();
    fit();
}

void ViewerState::viewAlong(const glm::vec3& dir) {
    if (!haveData_) return;
    takeOverCamera();
    core::Camera c = core::fitCamera(bounds_, viewSize(), -dir, options().fov);
    glm::vec3 up = turntableUp_;
    if (std::abs(glm::dot(up, dir)) > 0.99f) up = std::abs(dir.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    c.up = up;
    c.orthoHeight = options().ortho;
    if (c.orthographic()) c.eye = c.target - dir * bounds_.radius() * 3.0f;
    setCamera(c);
}

void ViewerState::key(const std::string& k) {
    auto stepTo = [this](int direction) {
        if (stepTimes.empty()) return;
        timePlaying = false;
        auto it = direction > 0 ? std::upper_bound(stepTimes.begin(), stepTimes.end(), time + 1e-12)
                                : std::lower_bound(stepTimes.begin(), stepTimes.end(), time - 1e-12);
        if (direction > 0) time = it == stepTimes.end() ? stepTimes.back() : *it;
        else time = it == stepTimes.begin() ? stepTimes.front() : *(it - 1);
    };
    if (k == "r") resetView();
    else if (k == "x") viewAlong({1, 0, 0});
    else if (k == "X") viewAlong({-1, 0, 0});
    else if (k == "y") viewAlong({0, 1, 0});
    else if (k == "Y") viewAlong({0, -1, 0});
    else if (k == "z") viewAlong({0, 0, 1});
    else if (k == "Z") viewAlong({0, 0, -1});
    else if (k == "space") paused = !paused;
    else if (k == "n") { paused = true; stepOnce = true; }
    else if (k == "m") {
        const auto& names = methods::kMethodNames;
        auto it = std::find_if(names.begin(), names.end(), [this](const auto& n) { return n.first == options().method; });
        const methods::Method next = it == names.end() || it + 1 == names.end() ? names.front().first : (it + 1)->first;
        edit([next](RenderOptions& o) { o.method = next; });
        compare.clear();
        requests_.rebuild = true;
    } else if (k == "c") {
        if (compare.empty())
            for (const auto& [m, name] : methods::kMethodNames) compare.push_back(m);
        else compare.clear();
        requests_.rebuild = true;
    } else if (k == "t") rotateMode = rotateMode == RotateMode::Turntable ? RotateMode::Trackball : RotateMode::Turntable;
    else if (k == "left") stepTo(-1);
    else if (k == "right") stepTo(+1);
    else if (k == "l") loop = !loop;
    else if (k == "h" || k == "f1") showPanel = !showPanel;
    else if (k == "p") {
        static int shot = 0;
        char name[64];
        std::snprintf(name, sizeof name, "flowsurf_screenshot_%03d.png", ++shot);
        const std::string& output = options().output;
        const bool own = output != "flowsurf.png" && outputKind(output) == OutputKind::Png;
        requests_.outputs.push_back({0, EventType::Screenshot, "", own ? output : name});
    } else if (k == "v") {
        if (recording) requests_.recordStop = true;
        else requests_.recordStart = outputKind(options().output) == OutputKind::Mp4 ? options().output
                                                                                      : "flowsurf_recording.mp4";
    } else if (k == "s") requests_.outputs.push_back({0, EventType::SaveConfig, "", "flowsurf_view.json"});
    else if (k == "k") requests_.outputs.push_back({0, EventType::SaveKeyframe, "", "flowsurf_camera_path.json"});
    else if (k == "q" || k == "escape") requests_.quit = true;
    else throw ConfigError("unknown key '" + k + "' (see the key list)");
}

void ViewerState::set(const std::string& name, const std::string& value) {
    // Settings only a viewer has.
    if (name == "compare") {
        compare = value == "off" || value == "none" ? std::vector<methods::Method>{} : parseMethodList(value, "compare");
        requests_.rebuild = true;
        return;
    }
    if (name == "rotate") {
        if (value != "turntable" && value != "trackball")
            throw ConfigError("rotate: '" + value + "' is not one of turntable, trackball");
        rotateMode = value == "turntable" ? RotateMode::Turntable : RotateMode::Trackball;
        return;
    }
    if (name == "paused") { paused = parseBool(name, value); return; }
    if (name == "time-playing") { timePlaying = parseBool(name, value); return; }
    if (name == "loop") { loop = parseBool(name, value); return; }
    if (name == "panel") { showPanel = parseBool(name, value); return; }
    if (name == "panel-collapsed") { panelCollapsed = parseBool(name, value); return; }
    if (name == "quality") {  // every N frames, or off
        char* end = nullptr;
        const long n = value == "off" ? 0 : std::strtol(value.c_str(), &end, 10);
        if (value != "off" && (value.empty() || *end != '\0' || n < 1 || n > 100000))
            throw ConfigError("quality: '" + value + "' is not a frame count 1..100000 or off");
        if (int(n) != playback_->quality().every()) playback_->quality().configure(int(n));  // a new setting starts a new log
        return;
    }
    if (name == "time-now") {
        double t = parseFloat(value, "time-now");
        time = std::clamp(t, std::min(timeStart, timeEnd), std::max(timeStart, timeEnd));
        return;
    }
    if (name == "speed") {  // data time per frame
        timePerFrame = parseFloat(value, "speed");
        return;
    }
    const OptionEffect effect = effectOf(name);  // throws ConfigError for an unknown name
    if (effect == OptionEffect::Camera) takeOverCamera();
    if (name == "size" || effect == OptionEffect::Reload) {
        RenderOptions checked = options();
        setOption(checked, name, value);  // throws ConfigError naming the option
        // The views' size is the window's (a resize asks for it); the input's options
        // are taken when the data is read again.
        if (name == "size")
            requests_.resize = glm::ivec2(checked.size.width * int(shownMethods().size()), checked.size.height);
        else requests_.reload.emplace_back(name, value);
        return;
    }
    playback_->set(name, value);  // throws ConfigError naming the option
    if (name == "up" && options().up) turntableUp_ = glm::normalize(*options().up);
    if (effect == OptionEffect::Rebuild) requests_.rebuild = true;
}

void ViewerState::handle(const Event& e) {
    try {
        switch (e.type) {
        case EventType::Set: set(e.name, e.value); break;
        case EventType::MouseMove: mouseMove(e.x, e.y); break;
        case EventType::MouseDown:
            dragButton_ = e.name;
            dragPan_ = e.name == "middle" || (e.name == "left" && e.shift);
            break;
        case EventType::MouseUp: dragButton_.clear(); dragPan_ = false; break;
        case EventType::Scroll: scroll(e.x); break;
        case EventType::Key: key(e.name); break;
        case EventType::Open: requests_.open = e.value; break;
        case EventType::Record: requests_.recordStart = e.value; break;
        case EventType::RecordStop: requests_.recordStop = true; break;
        case EventType::Resize: requests_.resize = glm::ivec2(int(e.x), int(e.y)); break;
        case EventType::Quit: requests_.quit = true; break;
        default: requests_.outputs.push_back(e); break;
        }
    } catch (const std::exception& ex) {
        error = ex.what();
    }
}

Requests ViewerState::takeRequests() {
    Requests r = std::move(requests_);
    requests_ = Requests{};
    return r;
}

RenderOptions ViewerState::batchOptions(uint32_t clock) const {
    RenderOptions b = options();
    b.size = viewSize();
    b.method = shownMethods().front();
    b.frames = int(clock);
    if (!stepTimes.empty() && !b.timeStepGiven) {
        // Frame k of the batch render shows data time start + k * perFrame: pick the start
        // so that frame `clock` shows the time on screen now.
        const bool moving = timePlaying && timePerFrame != 0.0;
        const double perFrame = moving ? timePerFrame : 0.0;
        b.timeRange = std::make_pair(time - double(clock) * perFrame, moving ? timeEnd : time);
        b.timePerFrame = std::abs(perFrame);
        b.framesPerStep = 0;
    }
    return b;
}

}  // namespace flowsurf::app::view
