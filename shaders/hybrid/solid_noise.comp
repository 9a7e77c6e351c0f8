// Hybrid solid noise N(r, t) [W §5]: a wrapped 3D texture fixed to the object. Each texel
// has a random phase (our hash) and cycles with the periodic profile w; a 3x3x3 binomial
// blur of the profiled values keeps the noise band-limited, so the two octave lookups of
// the constant-frequency scheme do not alias. The blurred value is rescaled to half the
// standard deviation of the unblurred profile (the blur alone would cut the texture
// contrast fourfold before the LIC averages it further).
// One invocation writes a row along x: it blurs each column of 3x3 profiled values across
// y and z once and slides the x blur along the row (9 hashes per texel instead of 27).
#include "common/noise.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
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
const float kW[3] = float[3](0.25, 0.5, 0.25);
// The y-z blur of the column at x.
float column(int x, int y, int z) {
    float sum = 0.0;
    for (int k = -1; k <= 1; ++k)
        for (int j = -1; j <= 1; ++j) sum += kW[j + 1] * kW[k + 1] * texelValue(ivec3(x, y + j, z + k));
    return sum;
}
void main() {
    const int y = int(gl_GlobalInvocationID.x), z = int(gl_GlobalInvocationID.y);
    if (y >= uSize || z >= uSize) return;
    float prev = column(-1, y, z), cur = column(0, y, z);
    for (int x = 0; x < uSize; ++x) {
        float next = column(x + 1, y, z);
        float sum = 0.25 * prev + 0.5 * cur + 0.25 * next;
        // sqrt(sum of squared 3D weights) = (0.25^2 + 0.5^2 + 0.25^2)^(3/2) = 0.2296; half
        // the unblurred deviation is restored (values stay mostly in [0, 1]).
        imageStore(uNoise, ivec3(x, y, z), vec4(0.5 + (sum - 0.5) * (0.5 / 0.2296)));
        prev = cur;
        cur = next;
    }
}
