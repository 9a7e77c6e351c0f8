// Contrast enhancement [doc/contrast.md]: the histogram of the flow texture over the surface's
// pixels (present/contrast_stretch.h).
layout(binding = CONTRAST_FLOW_UNIT) uniform sampler2D uFlow;    // F_a or I, channel r
layout(binding = CONTRAST_DEPTH_UNIT) uniform sampler2D uDepth;  // window depth, 1 = background

bool histogramValue(ivec2 px, out float value) {
    value = texelFetch(uFlow, px, 0).r;
    return texelFetch(uDepth, px, 0).r < 1.0;
}

#include "present/histogram.glsl"
