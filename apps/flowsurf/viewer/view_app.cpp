// The viewer's frame loop, shared by the window and the headless replay:
//   (1) input events of this frame (live input, panel edits, the replayed log) -> state
//   (2) what they ask for: open/reload data, rebuild renderers, resize, record
//   (3) render every view (the method's stage list, as `render` runs it)
//   (4) show it (window only), then this frame's outputs (screenshot, config, ...)
#include "view_app.h"

#include "session/camera_path_file.h"
#include "session/options/config_file.h"
#include "core/errors.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "io/image_writer.h"
#include "io/text_writer.h"
#include "io/video_writer.h"
#include "view_outputs.h"
#include "view_pipeline.h"
#include "view_state.h"
#include "view_window.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace flowsurf::app::view {

namespace {

using Clock = std::chrono::steady_clock;

class Session {
public:
    Session(const RenderOptions& o, const ViewOptions& v) : view_(v), state_(o), pipeline_(state_.playback()) {
        if (!v.compare.empty()) {
            state_.set("compare", v.compare);  // throws ConfigError naming a method it does not know
            state_.takeRequests();             // the first build comes with the data
        }
        if (!v.play.empty()) replay_ = readEventLog(v.play);
        if (v.headless && v.play.empty()) throw ConfigError("view --headless needs --play FILE (an event log)");
        const int n = int(state_.shownMethods().size());
        if (v.headless) {
            context_ = std::make_unique<gl::HeadlessContext>(o.verbose);
            renderer_ = context_->renderer();
        } else {
            // The views beside the panel: --size each, or what suits the screen [doc/contrast.md, the viewer's framing].
            window_ = std::make_unique<Window>(o.size.width * n, o.size.height, "flowsurf view", !v.sizeGiven);
            renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        }
        info_.renderer = renderer_;
        state_.setWindowSize(o.size.width * n, o.size.height);
        if (window_) {
            int w = 0, h = 0;
            window_->framebufferSize(&w, &h);  // the render area the window manager gave
            if (w > 0 && h > 0) state_.setWindowSize(w, h);
        }
        // The initial data: headless, an error ends the run; in a window it is shown.
        try {
            loadData(state_.options());
        } catch (const std::exception& e) {
            if (v.headless) throw;
            report(e.what());
        }
    }

    int run() {
        for (long frame = 0;; ++frame) {
            const auto t0 = Clock::now();
            // (1) input
            const bool idle = !lastRendered_ && next_ >= replay_.size();
            std::vector<Event> input = window_ ? window_->poll(frame, idle) : std::vector<Event>{};
            while (next_ < replay_.size() && replay_[next_].frame <= frame) input.push_back(replay_[next_++]);
            for (Event& e : input) {
                if (!resolveVisibleRange(e)) continue;
                state_.handle(e);
                if (!view_.recordEvents.empty()) {
                    recorded_.push_back(e);
                    recorded_.back().frame = frame;
                }
            }
            if (!state_.error.empty() && state_.error != lastError_) report(state_.error);
            // (2) requests
            Requests req = state_.takeRequests();
            applyRequests(req);
            // (3) render
            const bool rendered = renderIfNeeded();
            lastRendered_ = rendered;
            if (recorder_ && rendered) recordFrame();
            // (4) show, then outputs
            for (const Event& out : req.outputs)
                if (out.type == EventType::WindowShot && window_) window_->requestWindowShot(out.value);
            if (window_) window_->present(state_, pipeline_, info_);
            for (const Event& out : req.outputs) output(out);
            if (rendered && !view_.stats.empty()) frameMs_.push_back(msSince(t0));
            info_.frameMs = msSince(t0);
            if (rendered) state_.frameDone();
            const bool replayDone = next_ >= replay_.size();
            if (req.quit || (window_ && window_->closeRequested()) || (!window_ && replayDone)) break;
        }
        finish();
        return 0;
    }

private:
    static double msSince(Clock::time_point t0) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    }

    // `set color-range visible` (the panel's rescale button, or a log): the range of the
    // colour values the view shows now, set and recorded as MIN:MAX [doc/contrast.md, the viewer's framing]. False
    // (the event dropped, the error shown) when the view shows no such range.
    bool resolveVisibleRange(Event& e) {
        if (e.type != EventType::Set || e.value != "visible") return true;
        const OptionSpec* spec = findOption(e.name);
        if (!spec || spec->rescale != RangeRescale::DataAndView) return true;
        const std::optional<glm::vec2> r =
            pipeline_.ready() ? pipeline_.visibleColorRange(state_.time) : std::optional<glm::vec2>{};
        if (!r) {
            state_.error = e.name + " visible: the view shows no surface with a range of colour values";
            return false;
        }
        e.value = formatFloat(r->x) + ":" + formatFloat(r->y);
        return true;
    }

    void report(const std::string& message) {
        std::fprintf(stderr, "flowsurf view: %s\n", message.c_str());
        state_.error = message;
        lastError_ = message;
    }

    // Reads `o`'s input; the playback takes `o` only on success (a newly opened file comes
    // with its own camera and time).
    void loadData(const RenderOptions& o) {
        RenderOptions sized = o;
        sized.size = state_.viewSize();
        pipeline_.load(sized, state_.shownMethods());
        state_.dataLoaded(pipeline_.bounds(), pipeline_.times(), pipeline_.mapping());
        seenTimes_ = pipeline_.times();
        seenMapping_ = pipeline_.mapping();
        warmUp();
        if (window_) window_->setTitle("flowsurf view — " + o.input);
    }

    // New renderers for the options, the state's methods and view size.
    void build() {
        pipeline_.build(state_.viewSize(), state_.shownMethods());
        // Time options (--time, --time-per-frame, --time-step) change the time range.
        const core::TimeMapping& m = pipeline_.mapping();
        if (pipeline_.times() != seenTimes_ || m.start != seenMapping_.start || m.end != seenMapping_.end ||
            m.perFrame != seenMapping_.perFrame) {
            state_.setTimes(pipeline_.times(), m);
            seenTimes_ = pipeline_.times();
            seenMapping_ = m;
        }
        warmUp();
    }

    // ISA and IBFVS advect the warm-up frames (--warmup, default 3/alpha) out of sight, so
    // the first frame shown looks converged, as a batch movie's does (session/playback.h).
    void warmUp() {
        mustRender_ = true;
        pipeline_.playback().warmUp({state_.camera(), state_.time, state_.timePerFrame});
    }

    void applyRequests(const Requests& req) {
        if (req.resize) {
            if (window_) window_->resize(req.resize->x, req.resize->y);
            state_.setWindowSize(req.resize->x, req.resize->y);
        }
        if (window_) {
            int w = 0, h = 0;
            window_->framebufferSize(&w, &h);
            if (w > 0 && h > 0 && (w != state_.windowSize().width || h != state_.windowSize().height))
                state_.setWindowSize(w, h);
        }
        try {
            if (req.open || !req.reload.empty()) {
                RenderOptions o = state_.options();
                for (const auto& [name, value] : req.reload) setOption(o, name, value);
                if (req.open) {
                    o.input = *req.open;
                    o.field.clear();  // a new file has its own arrays
                    o.eye.reset(), o.target.reset();
                    o.timeRange.reset(), o.timeStepGiven = false;
                }
                loadData(o);
                if (req.open) state_.status = "opened " + o.input;
            }
        } catch (const std::exception& e) {
            report(e.what());  // the playback kept the data it had, and the options it was read with
        }
        const bool sizeChanged = pipeline_.ready() && (pipeline_.viewSize().width != state_.viewSize().width ||
                                                       pipeline_.viewSize().height != state_.viewSize().height ||
                                                       pipeline_.viewCount() != state_.shownMethods().size());
        if ((req.rebuild || sizeChanged) && pipeline_.ready()) {
            try {
                build();
            } catch (const std::exception& e) {
                report(e.what());
            }
        }
        if (req.recordStop) stopRecording();
        if (req.recordStart) {
            try {
                stopRecording();
                const core::Viewport v = pipeline_.viewSize();
                recorder_ = std::make_unique<io::VideoWriter>(
                    *req.recordStart, v.width * int(pipeline_.viewCount()), v.height,
                    io::VideoOptions{state_.options().fps, state_.options().crf});
                recordPath_ = *req.recordStart;
                state_.recording = true;
                state_.status = "recording " + recordPath_;
            } catch (const std::exception& e) {
                report(e.what());
            }
        }
    }

    bool renderIfNeeded() {
        if (!pipeline_.ready()) return false;
        core::Camera camera;
        try {
            camera = state_.camera();
        } catch (const std::exception& e) {
            report(e.what());
            state_.dropCameraPath();
            return false;
        }
        const bool changed = mustRender_ || !core::sameCamera(camera, lastCamera_) || state_.time != lastTime_;
        if (!state_.advancing() && !changed) return false;
        try {
            pipeline_.render({camera, state_.time, state_.timePerFrame}, state_.advancing());
        } catch (const std::exception& e) {
            report(e.what());
            state_.paused = true;  // a corrupt step: stop where it is rather than repeat the error
            return false;
        }
        lastCamera_ = camera;
        lastTime_ = state_.time;
        mustRender_ = false;
        if (++timerFrames_ >= 30) {  // the panel shows means over the last 30 frames
            for (size_t i = 0; i < pipeline_.viewCount(); ++i) {
                if (view_.stats.empty()) pipeline_.method(i).timer().reset();
            }
            timerFrames_ = 0;
        }
        return true;
    }

    void recordFrame() {
        int w = 0, h = 0;
        std::vector<uint8_t> img = pipeline_.readImage(&w, &h);
        try {
            recorder_->addFrame(img);
        } catch (const std::exception& e) {
            recorder_.reset();
            state_.recording = false;
            report(e.what());
        }
    }

    void stopRecording() {
        if (!recorder_) return;
        try {
            recorder_->finish();
            state_.status = "wrote " + recordPath_;
        } catch (const std::exception& e) {
            report(e.what());
        }
        recorder_.reset();
        state_.recording = false;
    }

    void output(const Event& e) {
        const session::Playback::Drawn& shown = pipeline_.playback().lastFrame();
        try {
            switch (e.type) {
            case EventType::WindowShot:
                if (window_) return;  // taken by present()
                [[fallthrough]];
            case EventType::Screenshot: {
                if (!pipeline_.ready()) throw ConfigError("screenshot: nothing rendered yet");
                int w = 0, h = 0;
                std::vector<uint8_t> img = pipeline_.readImage(&w, &h);
                io::writePngRgb8(e.value, w, h, 3, img);
                break;
            }
            case EventType::FlowTexture: {
                if (!pipeline_.ready()) throw ConfigError("flow-texture: nothing rendered yet");
                const core::Viewport v = pipeline_.viewSize();
                io::writePngGray16(e.value, v.width, v.height, gl::readGray16TopDown(pipeline_.method(0).flowTexture()));
                break;
            }
            // The frame on screen: the playback's last, numbered as a movie numbers it (its
            // warm-up comes before its frame 0).
            case EventType::SaveConfig: io::writeTextFile(e.value, configJson(state_.batchOptions(shown.clock))); break;
            case EventType::SaveKeyframe: appendKeyframe(e.value, shown.camera, uint32_t(shown.frame)); break;
            default: return;
            }
            state_.status = "wrote " + e.value;
            if (!state_.options().quiet) std::fprintf(stderr, "flowsurf view: wrote %s\n", e.value.c_str());
        } catch (const std::exception& ex) {
            report(ex.what());
        }
    }

    void finish() {
        stopRecording();
        if (!view_.recordEvents.empty()) {
            std::vector<Event> log = recorded_;
            log.push_back({long(log.empty() ? 0 : log.back().frame), EventType::Quit});
            io::writeTextFile(view_.recordEvents, formatEventLog(log));
        }
        if (!view_.stats.empty())
            io::writeTextFile(view_.stats, statsJson(pipeline_, frameMs_, renderer_, state_.playback().quality().every() > 0));
    }

    // In this order: the playback (in state_) goes while the GL context lives.
    ViewOptions view_;
    std::unique_ptr<gl::HeadlessContext> context_;
    std::unique_ptr<Window> window_;
    ViewerState state_;
    ViewPipeline pipeline_;
    std::vector<Event> replay_, recorded_;
    size_t next_ = 0;
    std::string renderer_, lastError_, recordPath_;
    FrameInfo info_;
    core::Camera lastCamera_;
    double lastTime_ = 0.0;
    bool mustRender_ = true;
    bool lastRendered_ = true;
    std::vector<double> seenTimes_;  // the steps' times and mapping the state was given
    core::TimeMapping seenMapping_;
    int timerFrames_ = 0;
    std::unique_ptr<io::VideoWriter> recorder_;
    std::vector<double> frameMs_;
};

}  // namespace

int runView(const RenderOptions& options, const ViewOptions& view) {
    Session session(options, view);
    return session.run();
}

}  // namespace flowsurf::app::view
