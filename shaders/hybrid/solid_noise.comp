// Hybrid solid noise N(r, t) [W §5]: a wrapped 3D texture fixed to the object. Each texel
// has a random phase (our hash) and cycles with the periodic profile w; a 3x3x3 binomial
// blur of the profiled values keeps the noise band-limited, so the two octave lookups of
// the constant-frequency scheme do not alias. The blurred value is rescaled to half the
// standard deviation of the unblurred profile (the blur alone would cut the texture
// contrast fourfold before the LIC averages it further).
// Written packed for the particle tracing's trilinear lookups (noiseTrilinear in
// particle_tracing.glsl): texel (x, y, z) holds, as 8-bit codes, N at (x, y, z),
// (x + 1, y, z), (x, y + 1, z) and (x + 1, y + 1, z), wrapped, so a lookup fetches two
// texels (z and z + 1) instead of eight. Code: 0.5 + NOISE_CODE (N - 0.5), which keeps
// the blurred square profile's extremes (0.5 +- 1.09) inside [0, 1]; the tracing decodes
// its average once per pixel. With SPARSE (oriented LIC) the texels are rare drops and the
// code is the value itself (0: no drop).
// One invocation writes ROWS rows along x (y0 .. y0 + ROWS - 1) at one z, so it blurs
// ROWS + 1 rows of N: it takes the profiled values of the ROWS + 3 rows around them at 3
// depths once per x, blurs across z, then y, and slides the x blur along the rows; the y-z
// part of each hash is taken once per row.
#include "core/noise.glsl"
layout(local_size_x = GROUP, local_size_y = GROUP, local_size_z = 1) in;
layout(binding = SOLID_NOISE_IMAGE_UNIT, r32ui) writeonly uniform uimage3D uPacked;  // the RGBA8 texture, as 32-bit words
uniform uint uFrame;
uniform float uPeriod;
uniform int uProfile;
uniform uint uSeed;
// Wrapped coordinate: p in [-1, 2 NOISE_SIZE) (no integer modulo: llvmpipe divides lane by lane).
int wrapped(int p) { return p < 0 ? p + NOISE_SIZE : (p >= NOISE_SIZE ? p - NOISE_SIZE : p); }
// The hash of texel (x, y, z) is hashPcg(x + rowHash(y, z)).
uint rowHash(int y, int z) { return hashPcg(uint(wrapped(y)) + hashPcg(uint(wrapped(z)) + hashPcg(uSeed))); }
#ifdef SPARSE
// Sparse noise for oriented LIC (SPARSE = the fraction of texels lit at a time): a texel is
// a drop for the first SPARSE of its cycle, which lasts uPeriod / (2 SPARSE) frames, so a
// drop lives half a period, as long as a dense texel stays on or off; over its life it
// follows the profile's rising part (square: 1 throughout; sawtooth: 0 to 1).
float texelValue(int x, uint row) {
    float life = fract(float(uFrame) * (2.0 * SPARSE / uPeriod) + hashToUnit(hashPcg(uint(wrapped(x)) + row)));
    return life < SPARSE ? (uProfile == NOISE_PROFILE_SQUARE ? 1.0 : life * (1.0 / SPARSE)) : 0.0;
}
#else
float texelValue(int x, uint row) {
    return noiseProfile(uProfile, float(uFrame) / uPeriod + hashToUnit(hashPcg(uint(wrapped(x)) + row)));
}
#endif
const float kW[3] = float[3](0.25, 0.5, 0.25);
// The y-z blurs at x of rows y0 .. y0 + ROWS (ROWS + 1 values), from the row hashes
// rows[3 j + k] of row y0 - 1 + j at depth z - 1 + k.
void columns(int x, uint rows[3 * (ROWS + 3)], out float col[ROWS + 1]) {
    float zBlur[ROWS + 3];
    for (int j = 0; j < ROWS + 3; ++j) {
        zBlur[j] = 0.0;
        for (int k = 0; k < 3; ++k) zBlur[j] += kW[k] * texelValue(x, rows[3 * j + k]);
    }
    for (int r = 0; r <= ROWS; ++r) col[r] = 0.25 * zBlur[r] + 0.5 * zBlur[r + 1] + 0.25 * zBlur[r + 2];
}
// sqrt(sum of squared 3D weights) = (0.25^2 + 0.5^2 + 0.25^2)^(3/2) = 0.2296; half the
// unblurred deviation is restored (N stays mostly in [0, 1]); then the code.
// Sparse: the value itself, a lone drop's centre (0.5^3 of its texel) scaled to 1.
#ifdef SPARSE
float code(float blurred) { return min(blurred * 8.0, 1.0); }
#else
float code(float blurred) { return 0.5 + NOISE_CODE * ((blurred - 0.5) * (0.5 / 0.2296)); }
#endif
void main() {
    const int y0 = int(gl_GlobalInvocationID.x) * ROWS, z = int(gl_GlobalInvocationID.y);
    if (y0 >= NOISE_SIZE || z >= NOISE_SIZE) return;
    uint rows[3 * (ROWS + 3)];
    for (int j = 0; j < ROWS + 3; ++j)
        for (int k = 0; k < 3; ++k) rows[3 * j + k] = rowHash(y0 - 1 + j, z + k - 1);
    float prev[ROWS + 1], cur[ROWS + 1], next[ROWS + 1], n0[ROWS + 1], n[ROWS + 1], nPrev[ROWS + 1];
    columns(-1, rows, prev);
    columns(0, rows, cur);
    for (int x = 0; x <= NOISE_SIZE; ++x) {
        // N at x (x = NOISE_SIZE: wrapped to 0, kept from the first column).
        if (x < NOISE_SIZE) {
            columns(x + 1, rows, next);
            for (int r = 0; r <= ROWS; ++r) {
                n[r] = code(0.25 * prev[r] + 0.5 * cur[r] + 0.25 * next[r]);
                prev[r] = cur[r];
                cur[r] = next[r];
            }
            if (x == 0) n0 = n;
        } else {
            n = n0;
        }
        if (x > 0)  // texel x - 1: N at x - 1 and x in rows r and r + 1
            for (int r = 0; r < ROWS; ++r)
                imageStore(uPacked, ivec3(x - 1, y0 + r, z),
                           uvec4(packUnorm4x8(vec4(nPrev[r], n[r], nPrev[r + 1], n[r + 1]))));
        nPrev = n;
    }
}
