// flowsurf — headless OpenGL 4.5 core context through EGL. Tries every EGL device
// (vendor drivers on a GPU machine) and then Mesa's surfaceless platform (llvmpipe),
// and logs which one it picked (GL_RENDERER).
#pragma once

#include "gl/objects.h"

#include <string>

namespace flowsurf::gl {

class HeadlessContext {
public:
    // Throws GlError with what was tried when no 4.5 core context can be made.
    explicit HeadlessContext(bool verbose = false);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& renderer() const { return renderer_; }
    // Makes this context current on the calling thread / releases it from the thread (so
    // another thread may make it current), with its RetiredPrograms (objects.h). Throws
    // GlError if EGL refuses.
    void makeCurrent();
    void release();
    const std::string& description() const { return description_; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string renderer_, description_;
    RetiredPrograms retired_;  // freed by the context's destruction
};

}  // namespace flowsurf::gl
