// Hybrid solid noise N(r, t) [W §5]: a wrapped 3D texture fixed to the object. Each texel
// has a random phase (our hash) and cycles with the periodic profile w; a 3x3x3 binomial
// blur of the profiled values keeps the noise band-limited, so the two octave lookups of
// the constant-frequency scheme do not alias. The blurred value is rescaled to half the
// standard deviation of the unblurred profile (the blur alone would cut the texture
// contrast fourfold before the LIC averages it further).
// One invocation writes a row along x: it blurs each column of 3x3 profiled values across
// y and z once and slides the x blur along the row (9 profiled values per texel instead
// of 27), with the y-z part of the 9 hashes taken once per row.
#include "common/noise.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) writeonly uniform image3D uNoise;
uniform int uSize;
uniform uint uFrame;
uniform float uPeriod;
uniform int uProfile;
uniform uint uSeed;
// Wrapped coordinate: p in [-1, uSize] (no integer modulo: llvmpipe divides lane by lane).
int wrapped(int p) { return p < 0 ? p + uSize : (p >= uSize ? p - uSize : p); }
// The hash of texel (x, y, z) is hashPcg(x + rowHash(y, z)): the y-z part, the same for a
// whole row along x, is taken once per row.
uint rowHash(int y, int z) { return hashPcg(uint(wrapped(y)) + hashPcg(uint(wrapped(z)) + hashPcg(uSeed))); }
float texelValue(int x, uint row) {
    return noiseProfile(uProfile, float(uFrame) / uPeriod + hashToUnit(hashPcg(uint(wrapped(x)) + row)));
}
const float kW[3] = float[3](0.25, 0.5, 0.25);
// The y-z blur of the column at x, from the 3 x 3 row hashes around the invocation's row.
float column(int x, uint rows[9]) {
    float sum = 0.0;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) sum += kW[j] * kW[k] * texelValue(x, rows[3 * k + j]);
    return sum;
}
void main() {
    const int y = int(gl_GlobalInvocationID.x), z = int(gl_GlobalInvocationID.y);
    if (y >= uSize || z >= uSize) return;
    uint rows[9];
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) rows[3 * k + j] = rowHash(y + j - 1, z + k - 1);
    float prev = column(-1, rows), cur = column(0, rows);
    for (int x = 0; x < uSize; ++x) {
        float next = column(x + 1, rows);
        float sum = 0.25 * prev + 0.5 * cur + 0.25 * next;
        // sqrt(sum of squared 3D weights) = (0.25^2 + 0.5^2 + 0.25^2)^(3/2) = 0.2296; half
        // the unblurred deviation is restored (values stay mostly in [0, 1]).
        imageStore(uNoise, ivec3(x, y, z), vec4(0.5 + (sum - 0.5) * (0.5 / 0.2296)));
        prev = cur;
        cur = next;
    }
}
