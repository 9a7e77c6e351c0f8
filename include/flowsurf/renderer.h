// flowsurf — renders flow textures of a Surface with one method (ISA, IBFVS or the hybrid
// LIC) into images in caller memory. Options are set by their command-line names and take
// the same values, ranges and defaults (`flowsurf render --help`); the same inputs, seed
// and frame count give the same image as the command line, byte for byte.
//
//   flowsurf::Renderer r;                       // its own headless EGL context
//   r.set("method", "hybrid");
//   r.set("size", "800x600");
//   r.render(surface, 90);                      // as `flowsurf render --frames 90`
//   std::vector<uint8_t> rgb(r.width() * r.height() * 3);
//   r.readImage(rgb.data());
#pragma once

#include <flowsurf/surface.h>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf {

// Whose OpenGL context renders. Own: the renderer makes a headless OpenGL 4.5 core
// context through EGL (any thread may use the renderer; calls are serialised). Current:
// the caller's context, current on the calling thread whenever the renderer is used (a
// viewer or a host application with a window).
enum class ContextMode { Own, Current };

struct CameraView {
    float eye[3] = {0, 0, 5};
    float target[3] = {0, 0, 0};
    float up[3] = {0, 1, 0};
    float fovDeg = 30.0f;      // vertical, perspective
    float orthoHeight = 0.0f;  // > 0: orthographic with this view height
};

// How faithful the texture is to the field it shows (doc/algorithms.md §9, the numbers of
// `flowsurf quality`); NaN where a metric has too few pixels, and for the correlations
// without the frame before.
struct QualityMetrics {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double orientationErrorDeg = kNone;     // median angle streaks vs projected field (deg)
    double orientationErrorP90Deg = kNone;  // its 90th percentile (deg)
    double countedFraction = kNone;         // surface pixels with coherent streaks, 0..1
    double frameCorrelation = kNone;        // consecutive frames, same pixels (1 frozen, 0 flicker)
    double frameCorrelationReprojected = kNone;  // ... following the surface with the camera
    double contrast = kNone;                // standard deviation of F_a over the surface
    double edgeContrastRatio = kNone;       // contrast near silhouettes / in the interior
    double frequencyPx = kNone;             // feature size across the flow (pixels)
    // The values by the names of the command line's JSON report, in its order.
    std::vector<std::pair<std::string, double>> named() const;
};
struct Quality {
    int frames = 0;          // frames measured
    QualityMetrics median;   // median over them
    QualityMetrics worst;    // worst frame per metric (highest error, lowest correlation...)
};

// One option as `flowsurf render --help` describes it: a row of the option table.
struct OptionInfo {
    std::string name;          // set()'s name, the command line's without dashes
    std::string group;         // Output, Data, Method, Overlay, Dye, Camera
    std::string help;          // one line
    std::string kind;          // flag, int, float, text, choice, size, vec3, color, path
    double min = 0.0, max = 0.0;       // inclusive range of int and float options
    std::vector<std::string> choices;  // the values a choice takes
    std::string defaultValue;  // as text; empty when it has none (e.g. the fitted camera)
    // What joins the numbers of a value given as several (size 800x600, time 0:1, x,y,z).
    std::string separator = ",";
    // The methods whose images the option changes ("isa", "ibfvs", "hybrid"; all of them
    // for most options).
    std::vector<std::string> methods;
};

class Renderer {
public:
    // Throws GlError when no OpenGL 4.5 core context can be made (ContextMode::Own).
    explicit Renderer(ContextMode mode = ContextMode::Own);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    // An option by its command-line name without dashes ("method", "size", "alpha",
    // "filter-length", "overlay", "eye", "orbit", "time-per-frame", ...) and its value as
    // text. Throws ConfigError naming the option for an unknown name or a bad value, and
    // for the options read with the input ("patches", "foam-case": Surface::read's) or
    // the command line's output files ("output", "fps", ...). After begin(), a camera
    // option keeps the animation going; any other starts it over at frame 0 (with the
    // warm-up) on the next advance().
    void set(const std::string& option, const std::string& value);
    std::string get(const std::string& option) const;
    // The names set() takes, in `--help` order.
    static std::vector<std::string> optionNames();
    // Those options described: group, help, kind, range, choices, default.
    static std::vector<OptionInfo> optionInfo();
    // The options Surface::read takes instead (Surface::readOptionNames()), described so.
    static std::vector<OptionInfo> readOptionInfo();

    // Dye (doc/algorithms.md §10): adds a source of ink at the surface point nearest `point` (object
    // space), `radius` in object units (0: a few pixels at the first frame's view), `color`
    // a name, #rrggbb or "r,g,b" (empty: the next of the default colours). As the "dye"
    // option (its value lists every source); a running animation goes on, the source
    // emitting from the next frame ("dye-release" frames, 0: continuously). Throws
    // ConfigError for a bad radius or colour.
    void addDye(const std::array<float, 3>& point, float radius = 0.0f, const std::string& color = "");

    // The camera: explicit, or (default, and after fitCamera) fitted to the surface's
    // bounds as the command line does. An orbit ("orbit" option) turns it per frame.
    void setCamera(const CameraView& view);
    void fitCamera();
    // The camera of the last rendered frame.
    CameraView camera() const;

    // Renders frames 0..frames of `surface` from a fresh start (the image after them is
    // what `flowsurf render --frames N` writes). Throws what loading a step throws.
    void render(const Surface& surface, int frames);
    // Starts an animation of `surface`: the warm-up ("warmup", default 3 / alpha frames
    // for ISA and IBFVS) runs now, then advance() renders frame 0, 1, 2, ... as `flowsurf
    // render -o movie.mp4` writes them (camera path, orbit and data time follow the frame;
    // frame f has noise clock W + f).
    void begin(const Surface& surface);
    void advance();
    // Frames rendered since render()/begin(); the frame on screen is frame() - 1.
    int frame() const;
    // Data time of the last frame (0 for steady data).
    double time() const;

    int width() const;
    int height() const;
    // The composite of the last frame, RGB8, rows top to bottom: width*height*3 bytes.
    void readImage(uint8_t* rgb) const;
    // The advected texture F_a alone, rows top to bottom: width*height values in [0, 1]
    // (float) or 0..65535 (as the command line's 16-bit --flow-texture PNG).
    void readFlowTexture(float* values) const;
    void readFlowTexture16(uint16_t* values) const;
    // Milliseconds per stage (mean over the frames of the last render() or advance()), in
    // the method's stage order.
    std::vector<std::pair<std::string, double>> stageMs() const;
    // GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string glRenderer() const;

    // Quality: measure every N-th frame of render() (its last frame, and the one before for
    // the correlations) and advance() (0, the default: off; a measured frame costs a
    // surface pass and a read-back). Takes effect at the next render() or begin().
    void setQualityEvery(int every);
    // The quality of the frames measured since render()/begin(). With nothing measured
    // (off), the last frame is measured now, without correlations. Throws ConfigError
    // before anything is rendered.
    Quality quality() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace flowsurf
