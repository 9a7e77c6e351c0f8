// Samples the previous F_a and injects the noise [L eq. 9] (every fragment is on the
// surface); also writes the overlay's shade (eye normal, colour value) and mask.
#include "common/resample.glsl"
#include "common/noise_injection.glsl"
layout(binding = 0) uniform sampler2D uPrevFlow;  // R32F, linear, clamp to edge
noperspective in vec2 vTexcoord;
in vec3 vNormalEye;
in float vColor;
in float vMask;
layout(location = 0) out vec4 outFlow;
layout(location = 1) out vec4 outShade;
layout(location = 2) out float outMask;
void main() {
    vec2 motionPx = gl_FragCoord.xy - vTexcoord * vec2(textureSize(uPrevFlow, 0));
    outFlow = vec4(injectNoise(resampleFlow(uPrevFlow, vTexcoord), gl_FragCoord.xy, motionPx), 0.0, 0.0, 1.0);
    outShade = vec4(normalize(vNormalEye), vColor);
    outMask = vMask;
}
