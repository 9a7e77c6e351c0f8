// IBFVS stages 2-3 per pixel, shared by polygon_advection.frag (fragment path) and
// polygon_advection.comp (compute path): the previous F_a resampled at the pixel's
// interpolated texture coordinate t = T(x - v dt) [L eq. 13, §IV-D.2], then the noise
// injected [L eq. 9] (every pixel of the projected surface S').
#include "image_space/resample.glsl"
#include "image_space/noise_injection.glsl"
layout(binding = IBFVS_PREV_FLOW_UNIT) uniform sampler2D uPrevFlow;  // R32F, linear, clamp to edge

float polygonAdvectedFlow(vec2 px, vec2 texcoord) {
    vec2 motionPx = px - texcoord * vec2(textureSize(uPrevFlow, 0));
    return injectNoise(resampleFlow(uPrevFlow, texcoord), px, motionPx);
}
