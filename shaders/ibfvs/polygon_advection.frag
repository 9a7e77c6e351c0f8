// Samples the previous F_a; also writes the overlay's shade (eye normal, true speed).
#include "common/resample.glsl"
layout(binding = 0) uniform sampler2D uPrevFlow;  // R32F, linear, clamp to edge
noperspective in vec2 vTexcoord;
in vec3 vNormalEye;
in float vSpeed;
layout(location = 0) out vec4 outFlow;
layout(location = 1) out vec4 outShade;
layout(location = 2) out vec2 outMotion;  // d' in pixels, for swept noise injection
void main() {
    outFlow = vec4(resampleFlow(uPrevFlow, vTexcoord), 0.0, 0.0, 1.0);
    outShade = vec4(normalize(vNormalEye), vSpeed);
    outMotion = gl_FragCoord.xy - vTexcoord * vec2(textureSize(uPrevFlow, 0));
}
