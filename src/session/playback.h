// flowsurf — the frame loop every front end runs: `render`, `compare`, the viewer,
// flowsurf::Renderer (and so Python), `bench` and the ParaView mapper are its clients, and
// it is the only caller of FlowMethod::renderFrame. One or more methods share one view of
// the same steps: it owns the surface of each frame (AnimatedSurface), the time levels, the
// camera of each frame, the noise clock, the warm-up, and what an option change means (the
// option table's effect column).
//
// The clock, one rule everywhere: after a (re)build the noise clock k counts every frame
// rendered, warm-up included. A warm-up renders W = warmupFrames() frames of the first
// frame's data and camera at k = 0..W-1; animation frame f then runs at k = W + f (a movie,
// Renderer::begin/advance and Python's Renderer.frames(), the viewer, ParaView). A single
// image has no warm-up: still(f) renders frames 0..f at k = 0..f (the frames before it
// converge it), or frame f alone when every method is history free.
#pragma once

#include "core/camera.h"
#include "core/time_series.h"
#include "methods/frame.h"
#include "session/animated_surface.h"
#include "session/dye_injection.h"
#include "session/options/options.h"
#include "session/quality_monitor.h"
#include "session/scene_setup.h"
#include "session/topology_overlay.h"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace flowsurf::session {

class Playback {
public:
    // A playback of `views` side by side, each at o.size (empty: o.method alone), with no
    // steps open yet: its options can be read and set (all of them, the input's included)
    // before open() makes the surface and the renderers. Needs no GL context. `group`: the
    // processes rendering this view together (ParaView under MPI), or null.
    explicit Playback(const RenderOptions& o = {}, std::vector<methods::Method> views = {},
                      methods::ProcessGroup* group = nullptr);
    ~Playback();
    Playback(const Playback&) = delete;
    Playback& operator=(const Playback&) = delete;

    // --- steps: open renders them, close lets them go -------------------------------------
    // Renders the steps of `steps` (which must outlive the playback, or close()) as a new
    // playback would: surface and renderers are made now, nothing is rendered yet, the
    // clock and the frame count start at 0. Needs a current GL 4.5 context; throws what
    // AnimatedSurface, FrameCameras and methods::makeRenderer throw, and the playback is
    // left closed. Options, views, stage timing and the quality setting stay.
    void open(core::StepProvider& steps);
    // Drops surface and renderers (with the GL context current) and forgets the steps.
    void close();
    bool isOpen() const { return steps_ != nullptr; }
    // open(steps) with options `o` (the input's included) in one step, for a front end that
    // reads its input again (the viewer's reload, File > Open): on success as open(); when
    // the new steps fail (ConfigError, IoError, ... rethrown), the playback is left as it
    // was: the steps it had open (which must still live), its options, views, surface,
    // renderers, textures and clock. The new surface and renderers are made while the old
    // ones live, so `steps` must be another provider than the open one.
    void reopen(core::StepProvider& steps, const RenderOptions& o);

    // --- options -----------------------------------------------------------------------
    const RenderOptions& options() const { return options_; }
    // Sets option `name` (ConfigError naming it for an unknown name or a bad value) and
    // does what the table's effect says: Camera: the frame cameras follow from the next
    // frame, textures and clock go on; Rebuild: surface and renderers are made anew before
    // the next frame and an animation starts over (with its warm-up); Output, None: nothing
    // here; Reload: taken while closed, refused (ConfigError) while open: the front end
    // opens the input again (close, set, open) or makes a new Playback. Returns the effect.
    OptionEffect set(const std::string& name, const std::string& value);
    // All options at once (the viewer's state, ParaView's properties): as set() for each
    // option that differs; returns the largest effect. Throws ConfigError on Reload while
    // open.
    OptionEffect setOptions(const RenderOptions& o);
    // The methods side by side (a Rebuild).
    void setViews(std::vector<methods::Method> views);
    // Makes surface and renderers anew now (the clock restarts), so errors show now; on
    // failure the options, views, surface and renderers of the last build that worked
    // are made again and the error is rethrown. ConfigError while closed.
    void rebuild();
    // The steps changed in place (ParaView hands over new data at each view time): the
    // surface is read and uploaded again; renderers, textures and clock go on.
    void stepsChanged();

    // --- an animation: camera (path, orbit) and data time follow the frame ----------------
    // Starts over at frame 0; with warm-up, the warm-up frames run first (a movie, the
    // library's animation); without, frame f runs at k = f.
    void start(bool warmUp);
    // Renders animation frame frame() and counts it.
    void advance();
    // The image `render --frames f` writes to a PNG: frames 0..f from a fresh start without
    // warm-up, or frame f alone when every method is history free.
    void still(int f);
    // Animation frames rendered since start() (the one shown is frame() - 1).
    int frame() const { return frame_; }  // 0 while closed

    // --- live: the camera and the data time come from outside (viewer, ParaView, bench) ---
    struct LiveFrame {
        core::Camera camera;
        double time = 0.0;      // data time (ignored for steady data)
        double perFrame = 0.0;  // data time per frame, for the hybrid's pathlines (0: streamlines)
    };
    // The warm-up frames at `at` (k = 0..W-1), after which the clock reads W.
    void warmUp(const LiveFrame& at);
    // One frame at noise clock clock(); then the clock advances unless `advance` is false
    // (a paused viewer drawing a camera move). An option change that rebuilt the renderers
    // restarts the clock at 0: call warmUp() after changing options.
    void render(const LiveFrame& f, bool advance = true);

    // Per-stage GPU timing of every method (FlowMethod::timer), kept over rebuilds. Off by
    // default: the timer waits for the GPU at every stage boundary.
    void setStageTiming(bool on);
    // Called after every frame rendered, warm-up included (a progress bar).
    void onFrame(std::function<void()> callback) { onFrame_ = std::move(callback); }

    // --- state and results ---------------------------------------------------------------
    uint32_t clock() const { return clock_; }  // noise clock of the next frame
    // W: options().warmup, or when it is -1 enough to look converged: 3 / alpha frames,
    // none when every method is history free (the hybrid's LIC: nothing builds up).
    int warmupFrames() const;
    // The methods side by side, in the order of the views (none while closed).
    std::span<const std::unique_ptr<methods::FlowMethod>> views() const { return methods_; }
    AnimatedSurface& surface() { return *surface_; }  // while open
    // The last frame rendered, warm-up included (all zero before the first).
    struct Drawn {
        core::Camera camera;
        double time = 0.0;    // data time (0: steady)
        uint32_t clock = 0;   // its noise clock k
        int frame = 0;        // k less the finished warm-up: animation frame f reads f, as a movie numbers it
        const skeleton::Skeleton* topology = nullptr;  // the flow topology it drew (--topology on)
    };
    const Drawn& lastFrame() const { return last_; }
    // Composites of every view side by side, RGB8, rows top to bottom.
    std::vector<uint8_t> readImage(int* width, int* height) const;

    // --- parts -----------------------------------------------------------------------------
    // The quality measurements (QualityMonitor: its setting, log and summaries), kept over
    // rebuilds; off by default.
    QualityMonitor& quality() { return quality_; }
    const QualityMonitor& quality() const { return quality_; }
    // The dye [doc/algorithms.md §10] (DyeInjection): it steps with each animation frame and
    // each live frame that advances the clock (not the warm-up), with the options of that
    // frame: dye changes apply live (effect None). Its field is null until a frame had a source.
    const DyeInjection& dye() const { return dye_; }

private:
    // What a build makes from the steps and options, before the playback takes it.
    struct Parts {
        std::unique_ptr<AnimatedSurface> surface;
        std::vector<std::unique_ptr<methods::FlowMethod>> methods;
        std::unique_ptr<TopologyOverlay> topology;  // --topology on
    };
    Parts make(const RenderOptions& o, core::StepProvider& steps) const;  // throws; changes nothing
    void install(Parts parts);          // the parts, and the clock, dye and quality restart for them
    void build();                       // surface, renderers, cameras from options_
    void requireOpen(const char* call) const;  // ConfigError naming `call` while closed
    bool historyFree() const;           // every method computes each frame afresh (FlowMethod::historyFree)
    bool applyPending();                // a pending rebuild (true) or camera change, before a frame
    void restart();                     // the animation over, after a rebuild
    static std::vector<methods::Method> shownViews(const std::vector<methods::Method>& views, const RenderOptions& o);
    // Every method's stage list once at noise clock k.
    void renderAll(const core::Camera& camera, double time, double perFrame, uint32_t k);
    void animationFrame(int f, uint32_t k);
    const FrameCameras& frameCameras();  // of the options, made when an animation needs them

    RenderOptions options_, built_;     // as set, and of the last build that worked
    core::StepProvider* steps_ = nullptr;  // null: closed
    methods::ProcessGroup* group_;
    // As asked for (empty: options().method alone), and of the last build that worked.
    std::vector<methods::Method> requestedViews_, builtViews_;
    std::unique_ptr<AnimatedSurface> surface_;
    std::vector<std::unique_ptr<methods::FlowMethod>> methods_;
    std::unique_ptr<TopologyOverlay> topology_;
    std::unique_ptr<FrameCameras> cameras_;
    bool rebuildPending_ = false, camerasPending_ = false;
    bool stageTiming_ = false;
    bool started_ = false, startWarm_ = false;  // an animation runs (and began with its warm-up)
    int frame_ = 0;
    int warmedUp_ = 0;                  // warm-up frames on the clock since the build
    uint32_t clock_ = 0;
    Drawn last_;
    std::function<void()> onFrame_;
    QualityMonitor quality_;
    DyeInjection dye_;
};

}  // namespace flowsurf::session
