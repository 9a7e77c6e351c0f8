#include "methods/common/shader_interface.h"

#include "core/noise.h"
#include "methods/common/dye.h"
#include "methods/common/params.h"
#include "methods/common/percentile_range.h"
#include "methods/common/surface_gpu.h"
#include "methods/common/visibility_buffer.h"
#include "methods/common/time_levels.h"

#include <cctype>

namespace flowsurf::methods {

namespace {
// PREFIX_NAME value for each entry of a name table: "gray-lit" -> OVERLAY_GRAY_LIT.
template <typename E, size_t N>
std::string enumDefines(const char* prefix, const EnumNames<E, N>& names) {
    std::string out;
    for (const auto& [value, name] : names) {
        std::string id = prefix;
        id += '_';
        for (char c : name) id += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
        out += "#define " + id + " " + std::to_string(int(value)) + "\n";
    }
    return out;
}
}  // namespace

const std::string& shaderInterface() {
    static const std::string defines = [] {
        std::string s = "#define NOISE_MEAN " + std::to_string(core::kNoiseMean) + "\n";
        s += "#define MAX_LEVELS " + std::to_string(TimeLevelSource::kMaxLevels) + "\n";
        s += enumDefines("NOISE_PROFILE", kNoiseProfileNames);
        s += enumDefines("OVERLAY", kOverlayNames);
        s += enumDefines("KERNEL", kKernelNames);
        s += enumDefines("INTEGRATOR", kIntegratorNames);
        s += enumDefines("EDGE_FILL", kEdgeFillNames);
        s += "#define VERTEX_TEXELS " + std::to_string(SurfaceGpu::kVertexFloats / 4) + "\n";
        for (const auto& [name, value] : {std::pair<const char*, int>{"VIS_VERTEX_UNIT", kVisVertexUnit},
                                          {"VIS_TRIANGLE_UNIT", kVisTriangleUnit},
                                          {"VIS_DEPTH_BINDING", kVisDepthBinding},
                                          {"VIS_ID_BINDING", kVisIdBinding},
                                          {"VIS_INDIRECT_BINDING", kVisIndirectBinding},
                                          {"VIS_DEFERRED_BINDING", kVisDeferredBinding},
                                          {"VIS_DEFERRED_ID_BINDING", kVisDeferredIdBinding},
                                          {"VIS_COVERING_BINDING", kVisCoveringBinding},
                                          {"VIS_RASTER_GROUP", kVisRasterGroup}})
            s += std::string("#define ") + name + " " + std::to_string(value) + "\n";
        s += "#define PIXEL_GROUP " + std::to_string(kPixelGroup) + "\n";
        s += "#define HISTOGRAM_BINDING " + std::to_string(kHistogramBinding) + "\n";
        s += "#define HISTOGRAM_BINS " + std::to_string(PercentileRange::kBins) + "\n";
        s += "#define HISTOGRAM_TILE " + std::to_string(PercentileRange::kTilePx) + "\n";
        s += "#define CONTRAST_FLOW_UNIT " + std::to_string(kContrastFlowUnit) + "\n";
        s += "#define CONTRAST_DEPTH_UNIT " + std::to_string(kContrastDepthUnit) + "\n";
        s += "#define DYE_GROUP " + std::to_string(kDyeGroup) + "\n";
        s += "#define DYE_INDEX_UNIT " + std::to_string(kDyeIndexUnit) + "\n";
        s += "#define DYE_VALUE_BINDING " + std::to_string(kDyeValueBinding) + "\n";
        s += "#define DYE_BAND_BINDING " + std::to_string(kDyeBandBinding) + "\n";
        s += "#define DYE_SOURCE_BINDING " + std::to_string(kDyeSourceBinding) + "\n";
        s += "#define DYE_DEPARTURE_BINDING " + std::to_string(kDyeDepartureBinding) + "\n";
        s += "#define DYE_FLAG_BINDING " + std::to_string(kDyeFlagBinding) + "\n";
        s += "#define DYE_ACTIVE_BINDING " + std::to_string(kDyeActiveBinding) + "\n";
        return s;
    }();
    return defines;
}

void dispatchPerPixel(int width, int height) {
    glDispatchCompute(GLuint((width + kPixelGroup - 1) / kPixelGroup), GLuint((height + kPixelGroup - 1) / kPixelGroup), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT);
}

gl::Program program(std::initializer_list<std::pair<GLenum, std::string>> stages, const std::string& defines) {
    return gl::Program(stages, shaderInterface() + defines);
}

}  // namespace flowsurf::methods
