// Hybrid particle tracing as a fragment pass: one full-screen triangle, the LIC loop per
// covered pixel (hybrid/particle_tracing.glsl); background pixels keep the cleared gray.
#include "hybrid/particle_tracing.glsl"
out vec4 outLic;
void main() {
    float lic;
    if (!licAt(ivec2(gl_FragCoord.xy), lic)) discard;
    outLic = vec4(lic, 0.0, 0.0, 1.0);
}
