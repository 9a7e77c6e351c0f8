// Noise injection and blending, [L] eq. 9: F_a <- (1 - gamma) F_a + gamma G, gamma = alpha
// on the projected surface S' and 0 elsewhere. The blend itself is fixed-function
// (constant alpha); this shader supplies G and drops background fragments.
#include "common/noise.glsl"
layout(binding = 0) uniform sampler2D uDepth;  // window depth of the surface, 1 = background
uniform uint uFrame;
uniform float uScale;
uniform float uPeriod;
uniform int uProfile;
uniform uint uSeed;
out vec4 outG;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(uDepth, px, 0).r >= 1.0) discard;  // gamma = 0 off the surface
    float g = noiseAt(gl_FragCoord.xy, uFrame, uScale, uPeriod, uProfile, uSeed);
    outG = vec4(g, g, g, 1.0);
}
