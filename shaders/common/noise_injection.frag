// Noise injection and blending, [L] eq. 9: F_a <- (1 - gamma) F_a + gamma G, gamma = alpha
// on the projected surface S' and 0 elsewhere. The blend itself is fixed-function
// (constant alpha); this shader supplies G and drops background fragments.
// NOISE_SWEPT: G averaged over the segment x - t d', t in [0,1), that the texture at x
// came along in this frame (d' from the advection pass): what continuous injection
// along the pathline would deposit. One sample per noise cell, at most kMaxSweep.
#include "common/noise.glsl"
layout(binding = 0) uniform sampler2D uDepth;  // window depth of the surface, 1 = background
layout(binding = 1) uniform sampler2D uMotion; // RG16F: d' = x - (backward coordinate), pixels
const int kMaxSweep = 8;
uniform uint uFrame;
uniform float uScale;
uniform float uPeriod;
uniform int uProfile;
uniform uint uSeed;
out vec4 outG;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(uDepth, px, 0).r >= 1.0) discard;  // gamma = 0 off the surface
#ifdef NOISE_SWEPT
    vec2 d = texelFetch(uMotion, px, 0).xy;
    int n = clamp(int(ceil(length(d) / uScale)), 1, kMaxSweep);
    float g = 0.0;
    uint seedHash = hashPcg(uSeed);
    for (int i = 0; i < n; ++i)
        g += noiseAtSeeded(gl_FragCoord.xy - d * ((float(i) + 0.5) / float(n)), uFrame, uScale, uPeriod, uProfile,
                           seedHash);
    g /= float(n);
#else
    float g = noiseAt(gl_FragCoord.xy, uFrame, uScale, uPeriod, uProfile, uSeed);
#endif
    outG = vec4(g, g, g, 1.0);
}
