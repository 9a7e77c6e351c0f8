// Hybrid solid noise N(r, t) [W §5]: a wrapped 3D texture fixed to the object. Each texel
// has a random phase (CPU, our hash) and cycles with the periodic profile w; a 3x3x3
// binomial blur of the profiled values keeps the noise band-limited, so the two octave
// lookups of the constant-frequency scheme do not alias. The blurred value is rescaled to
// the standard deviation of the unblurred profile (the blur alone would cut the texture
// contrast fourfold before the LIC averages it further).
#include "common/noise.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, r32f) writeonly uniform image3D uNoise;
uniform int uSize;
uniform uint uFrame;
uniform float uPeriod;
uniform int uProfile;
uniform uint uSeed;
float texelValue(ivec3 p) {
    p = (p + uSize) % uSize;  // wrapped
    uint h = hashPcg(uint(p.x) + hashPcg(uint(p.y) + hashPcg(uint(p.z) + hashPcg(uSeed))));
    return noiseProfile(uProfile, float(uFrame) / uPeriod + hashToUnit(h));
}
void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, ivec3(uSize)))) return;
    const float w[3] = float[3](0.25, 0.5, 0.25);
    float sum = 0.0;
    for (int k = -1; k <= 1; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) sum += w[i + 1] * w[j + 1] * w[k + 1] * texelValue(p + ivec3(i, j, k));
    // sqrt(sum of squared 3D weights) = (0.25^2 + 0.5^2 + 0.25^2)^(3/2) = 0.2296; half the
    // unblurred deviation is restored (values stay mostly in [0, 1]).
    imageStore(uNoise, p, vec4(0.5 + (sum - 0.5) * (0.5 / 0.2296)));
}
