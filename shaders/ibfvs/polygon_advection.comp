// IBFVS stages 2-3, compute path: per pixel of the surface, the texture coordinate the
// advection draw interpolated (RG32F) -> resampled F_a with the noise injected
// (ibfvs/polygon_advection.glsl); the gray flow background elsewhere [L §IV-F.2].
#include "ibfvs/polygon_advection.glsl"
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = IBFVS_TEXCOORD_UNIT) uniform sampler2D uTexcoord;  // RG32F, from the draw
layout(binding = IBFVS_DEPTH_UNIT) uniform sampler2D uDepth;        // the draw's depth, 1 = background
layout(binding = IBFVS_NEXT_FLOW_IMAGE_UNIT, r32f) writeonly uniform image2D uNextFlow;
uniform float uFlowBackground;
uniform ivec2 uOrigin;  // the pixels written: [uOrigin, uEnd) (the whole image, or a parallel render's piece)
uniform ivec2 uEnd;
void main() {
    ivec2 p = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uEnd))) return;
    float f = uFlowBackground;
    if (texelFetch(uDepth, p, 0).r < 1.0) f = polygonAdvectedFlow(vec2(p) + 0.5, texelFetch(uTexcoord, p, 0).xy);
    imageStore(uNextFlow, p, vec4(f));
}
