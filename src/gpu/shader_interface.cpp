#include "gpu/shader_interface.h"

#include "core/noise.h"
#include "gpu/shader_limits.h"
#include "params/params.h"

#include <cctype>
#include <cstdio>

namespace flowsurf::methods {

namespace {
std::string define(const std::string& name, int value) { return "#define " + name + " " + std::to_string(value) + "\n"; }

// PREFIX_NAME value for each entry of a name table: "gray-lit" -> OVERLAY_GRAY_LIT.
template <typename E, size_t N>
std::string enumDefines(const char* prefix, const EnumNames<E, N>& names) {
    std::string out;
    for (const auto& [value, name] : names) {
        std::string id = prefix;
        id += '_';
        for (char c : name) id += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
        out += define(id, int(value));
    }
    return out;
}
}  // namespace

const std::string& shaderInterface() {
    static const std::string defines = [] {
        std::string s = "#define NOISE_MEAN " + std::to_string(core::kNoiseMean) + "\n";
        s += define("MAX_LEVELS", kMaxTimeLevels);
        s += enumDefines("NOISE_PROFILE", kNoiseProfileNames);
        s += enumDefines("OVERLAY", kOverlayNames);
        s += enumDefines("KERNEL", kKernelNames);
        s += enumDefines("INTEGRATOR", kIntegratorNames);
        s += enumDefines("EDGE_FILL", kEdgeFillNames);
        s += define("VERTEX_TEXELS", surface_vertex::kTexels);
        s += define("VIS_RASTER_GROUP", kVisRasterGroup);
        s += define("VIS_OCCLUDER_CELL", kVisOccluderCellPx);
        s += define("PIXEL_GROUP", kPixelGroup);
        s += define("HISTOGRAM_BINS", kHistogramBins);
        s += define("HISTOGRAM_TILE", kHistogramTilePx);
        s += define("DYE_GROUP", kDyeGroup);
        char visible[32];
        std::snprintf(visible, sizeof visible, "%.9e", double(kDyeVisible));
        s += std::string("#define DYE_VISIBLE ") + visible + "\n";
        for (const BindingPoint& b : kBindingPoints) s += define(b.glsl, b.point);
        for (const BindingPoint& o : kFragmentOutputs) s += define(o.glsl, o.point);
        for (const VertexAttribute& a : kVertexAttributes) {
            s += define(std::string(a.glsl) + "_LOCATION", a.location);
            s += define(std::string(a.glsl) + "_OFFSET", a.offset);
        }
        return s;
    }();
    return defines;
}

void dispatchPerPixel(int width, int height) {
    glDispatchCompute(GLuint((width + kPixelGroup - 1) / kPixelGroup), GLuint((height + kPixelGroup - 1) / kPixelGroup), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT);
}

void enableAttribute(GLuint vao, const VertexAttribute& a) {
    glEnableVertexArrayAttrib(vao, GLuint(a.location));
    glVertexArrayAttribFormat(vao, GLuint(a.location), a.components, GL_FLOAT, GL_FALSE, GLuint(a.offset * sizeof(float)));
    glVertexArrayAttribBinding(vao, GLuint(a.location), a.buffer);
}

gl::Program program(std::initializer_list<std::pair<GLenum, std::string>> stages, const std::string& defines) {
    return gl::Program(stages, shaderInterface() + defines);
}

}  // namespace flowsurf::methods
