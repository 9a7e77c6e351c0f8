// ISA stages 3-4, fragment path (isa/texture_advection.glsl): the mesh warp's grid
// triangles (texture_advection.vert) or, PER_PIXEL, one full-screen triangle into the
// next F_a.
#include "isa/texture_advection.glsl"
#ifndef PER_PIXEL
in vec2 vTexcoord;
in float vEdge;
#endif
layout(location = FLOW_OUT) out vec4 outFlow;
void main() {
#ifdef PER_PIXEL
    vec4 m = meshAtPixel(gl_FragCoord.xy);
    outFlow = vec4(advectedFlow(gl_FragCoord.xy, m.xy, m.z), 0.0, 0.0, 1.0);
#else
    outFlow = vec4(advectedFlow(gl_FragCoord.xy, vTexcoord, vEdge), 0.0, 0.0, 1.0);
#endif
}
