// Samples the previous F_a and injects the noise [L eq. 9] (ibfvs/polygon_advection.glsl);
// also writes the overlay's shade (eye normal, colour value) and mask. ADVECT_IN_COMPUTE
// (the compute path): writes the texture coordinate instead, and polygon_advection.comp
// does the per-pixel work.
#include "ibfvs/polygon_advection.glsl"
noperspective in vec2 vTexcoord;
in vec3 vNormalEye;
in float vColor;
in float vMask;
layout(location = FLOW_OUT) out vec4 outFlow;  // ADVECT_IN_COMPUTE: RG32F texture coordinate
layout(location = SHADE_OUT) out vec4 outShade;
layout(location = MASK_OUT) out float outMask;
void main() {
#ifdef ADVECT_IN_COMPUTE
    outFlow = vec4(vTexcoord, 0.0, 1.0);
#else
    outFlow = vec4(polygonAdvectedFlow(gl_FragCoord.xy, vTexcoord), 0.0, 0.0, 1.0);
#endif
    outShade = vec4(normalize(vNormalEye), vColor);
    outMask = vMask;
}
