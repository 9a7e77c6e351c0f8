#include "gl/context.h"

#include "core/errors.h"
#include "gl/objects.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <vector>

namespace flowsurf::gl {

namespace {

template <typename Fn>
Fn eglProc(const char* name) {
    return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

// Makes a 4.5 core context on an initialised display; returns nullptr on failure.
EGLContext makeContext(EGLDisplay dpy) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor)) return EGL_NO_CONTEXT;
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless: any config (or none, with EGL_KHR_no_config_context) will do.
    eglChooseConfig(dpy, configAttribs, &config, 1, &count);
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) return EGL_NO_CONTEXT;
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        return EGL_NO_CONTEXT;
    }
    return ctx;
}

// Mesa (22.3) fills its table of depth/stencil texture-store functions on the process's first
// depth upload, unguarded (texstore_depth_stencil: clear the table, fill it, set a flag): two
// contexts on two threads making their first depth upload at once can read the table while
// the other clears it, and call a null function. Threads of one group (methods::ThreadGroup)
// do exactly that, so the first context of the process makes one depth upload alone, before
// it is handed out. Harmless on drivers without the table.
void fillDriverTablesOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        const Texture2D depth(GL_DEPTH_COMPONENT32F, 1, 1, GL_NEAREST);
        const float one = 1.0f;
        glTextureSubImage2D(depth.id(), 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
        glFinish();
    });
}

}  // namespace

HeadlessContext::HeadlessContext(bool verbose) {
    std::vector<std::pair<EGLDisplay, std::string>> candidates;
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    std::string tried;
    if (queryDevices && getPlatformDisplay) {
        EGLDeviceEXT devices[16];
        EGLint n = 0;
        if (queryDevices(16, devices, &n)) {
            for (EGLint i = 0; i < n; ++i) {
                const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
                std::string name = "EGL device " + std::to_string(i);
                if (ext && std::string(ext).find("EGL_MESA_device_software") != std::string::npos)
                    name += " (software)";
                EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY) candidates.emplace_back(d, name);
            }
        }
    }
    if (getPlatformDisplay) {
        EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) candidates.emplace_back(d, "Mesa surfaceless platform");
    }
    // Prefer hardware devices: the software device goes last.
    std::stable_partition(candidates.begin(), candidates.end(),
                          [](const auto& c) { return c.second.find("software") == std::string::npos &&
                                                     c.second.find("surfaceless") == std::string::npos; });
    for (auto& [dpy, name] : candidates) {
        EGLContext ctx = makeContext(dpy);
        if (ctx == EGL_NO_CONTEXT) {
            tried += (tried.empty() ? "" : "; ") + name + ": no OpenGL 4.5 core context";
            continue;
        }
        display_ = dpy;
        context_ = ctx;
        int major = 0, minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        description_ = name + ", GL " + std::to_string(major) + "." + std::to_string(minor) + ", " + renderer_;
        if (major * 10 + minor < 45) {
            eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(dpy, ctx);
            display_ = context_ = nullptr;
            tried += (tried.empty() ? "" : "; ") + description_ + ": below 4.5";
            continue;
        }
        fillDriverTablesOnce();
        RetiredPrograms::makeCurrent(&retired_);
        if (verbose) std::fprintf(stderr, "flowsurf: OpenGL on %s\n", description_.c_str());
        return;
    }
    throw GlError("no OpenGL 4.5 core context could be created headless through EGL (" +
                  (tried.empty() ? std::string("no EGL device or platform found") : tried) +
                  "); install Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver");
}

void HeadlessContext::makeCurrent() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw GlError("cannot make the headless OpenGL context current (EGL error 0x" +
                      std::to_string(eglGetError()) + ")");
    RetiredPrograms::makeCurrent(&retired_);
}

void HeadlessContext::release() {
    if (RetiredPrograms::current() == &retired_) RetiredPrograms::makeCurrent(nullptr);
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

HeadlessContext::~HeadlessContext() {
    if (RetiredPrograms::current() == &retired_) RetiredPrograms::makeCurrent(nullptr);
    if (display_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        // The display is not terminated: other contexts (tests) may share it.
    }
}

}  // namespace flowsurf::gl
