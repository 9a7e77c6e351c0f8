// ISA stages 3-4, compute path, pixel warp (isa/texture_advection.glsl): one invocation
// per pixel writes the next F_a (R32F image).
#include "isa/texture_advection.glsl"
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = ISA_NEXT_FLOW_IMAGE_UNIT, r32f) writeonly uniform image2D uNextFlow;
uniform ivec2 uOrigin;  // the pixels written: [uOrigin, uEnd) (a parallel render's tile)
uniform ivec2 uEnd;
void main() {
    ivec2 p = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uEnd))) return;
    vec2 px = vec2(p) + 0.5;  // pixel centre, as gl_FragCoord
    vec4 m = meshAtPixel(px);
    imageStore(uNextFlow, p, vec4(advectedFlow(px, m.xy, m.z)));
}
