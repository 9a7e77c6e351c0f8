// Noise G of §1 item 4 ([L] eq. 9's G): mirrors src/core/noise.cpp (same hash).
uint hashPcg(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
uint hashCell(int ix, int iy, uint seed) {
    return hashPcg(uint(ix) + hashPcg(uint(iy) + hashPcg(seed)));
}
float hashToUnit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }

// Periodic profile w: NOISE_PROFILE_SQUARE or NOISE_PROFILE_SAWTOOTH.
float noiseProfile(int profile, float t) {
    t = fract(t);
    return profile == NOISE_PROFILE_SQUARE ? (t < 0.5 ? 1.0 : 0.0) : t;
}
float noiseCell(int ix, int iy, uint frame, float period, int profile, uint seed) {
    float phase = hashToUnit(hashCell(ix, iy, seed));
    return noiseProfile(profile, float(frame) / period + phase);
}
// G(x; k), x in pixels: bilinear interpolation (triangular pulse h) of cell values.
float noiseAt(vec2 px, uint frame, float scale, float period, int profile, uint seed) {
    vec2 u = px / scale - 0.5;
    vec2 f = floor(u);
    ivec2 i = ivec2(f);
    vec2 a = u - f;
    float g00 = noiseCell(i.x, i.y, frame, period, profile, seed);
    float g10 = noiseCell(i.x + 1, i.y, frame, period, profile, seed);
    float g01 = noiseCell(i.x, i.y + 1, frame, period, profile, seed);
    float g11 = noiseCell(i.x + 1, i.y + 1, frame, period, profile, seed);
    return mix(mix(g00, g10, a.x), mix(g01, g11, a.x), a.y);
}
