// flowsurf — what a method gets each frame, and the interface every method implements.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "gl/stage_timer.h"
#include "parallel/pixel_rect.h"
#include "parallel/tile_traffic.h"
#include "params/params.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace flowsurf::methods {

class SurfaceGpu;
struct TimeLevels;
class ProcessGroup;
struct DyeView;

struct FrameInput {
    const SurfaceGpu* surface = nullptr;  // the surface at this frame's data time
    core::Camera camera;
    uint32_t frame = 0;                   // k: the clock of the noise
    // Unsteady data around this frame's data time, for methods that integrate through
    // time (usesTimeLevels()); null or empty: the surface's field is used throughout.
    const TimeLevels* levels = nullptr;
    // The dye to show over the texture in the overlay (session::Playback's), or null.
    const DyeView* dye = nullptr;
};

class FlowMethod {
public:
    virtual ~FlowMethod() = default;
    virtual const char* name() const = 0;
    // Runs the paper's stage list for frame k (see each orchestrator).
    virtual void renderFrame(const FrameInput& in) = 0;
    // F_a: the advected flow texture alone (R32F, channel r).
    virtual const gl::Texture2D& flowTexture() const = 0;
    // The displayed image after the overlay (RGBA8).
    virtual const gl::Texture2D& composite() const = 0;
    // Window depth of the surface for the last frame (1 = background): the surface mask.
    virtual const gl::Texture2D& surfaceDepth() const = 0;
    // The last frame's surface attributes per pixel (RGBA16F): xyz the eye-space normal, w
    // the colour value 0..1 (NaN: none): what a host's own colouring of the surface needs.
    virtual const gl::Texture2D& surfaceShade() const = 0;
    // True if the last renderFrame ran the dynamic case.
    virtual bool lastFrameDynamic() const = 0;
    // True if the method reads FrameInput::levels (the hybrid's pathlines through
    // unsteady data); ISA and IBFVS integrate through time frame by frame instead.
    virtual bool usesTimeLevels() const { return false; }
    // True if frame k depends only on this frame's input (the hybrid's LIC [W]): a single
    // image of frame k needs no frames before it. ISA and IBFVS carry F_a from frame to frame.
    virtual bool historyFree() const { return false; }
    gl::StageTimer& timer() { return timer_; }
    // What the last frame exchanged with the other processes (parallel = tiles); zero
    // otherwise. Reset at each frame's start by the methods that tile.
    virtual TileTraffic tileTraffic() const { return {}; }

protected:
    gl::StageTimer timer_;
};

// Object-space time step so that the fastest vector moves at most stepPx pixels. `group`:
// the processes rendering this view together (ImageWork::group), each holding one piece.
float dtForStep(const FrameInput& in, const core::Viewport& viewport, float stepPx,
                const ProcessGroup* group = nullptr);

}  // namespace flowsurf::methods
