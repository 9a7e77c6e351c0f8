// Resampling of the previous F_a at a backward-integrated coordinate [L eq. 12, 13],
// shared by ISA's and IBFVS's texture advection. Default: the texture's bilinear filter,
// as in [L]. Its numerical diffusion (variance a(1-a) px^2 per frame and axis for a
// fractional offset a) blurs across the flow as much as along it, frame after frame.
// RESAMPLE_BICUBIC: Catmull-Rom (4 x 4 texels, interpolating), clamped to the range of the
// four nearest texels; it keeps features of 4 px period ~0.88 per frame where bilinear
// keeps ~0.71 at the worst offset.
#ifdef RESAMPLE_BICUBIC
// Catmull-Rom weights for the texels at offsets -1, 0, 1, 2 from the one below t.
vec4 catmullRomWeights(float t) {
    float t2 = t * t, t3 = t2 * t;
    return vec4(-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0, -1.5 * t3 + 2.0 * t2 + 0.5 * t,
                0.5 * t3 - 0.5 * t2);
}
float resampleFlow(sampler2D tex, vec2 uv) {
    ivec2 size = textureSize(tex, 0);
    vec2 p = uv * vec2(size) - 0.5;  // texel-centre coordinates
    vec2 base = floor(p);
    vec2 t = p - base;
    vec4 wx = catmullRomWeights(t.x), wy = catmullRomWeights(t.y);
    ivec2 i0 = ivec2(base) - 1;
    float sum = 0.0, lo = 1e30, hi = -1e30;
    for (int j = 0; j < 4; ++j) {
        int y = clamp(i0.y + j, 0, size.y - 1);  // clamp to edge, as the bilinear sampler
        vec4 row;
        for (int i = 0; i < 4; ++i) row[i] = texelFetch(tex, ivec2(clamp(i0.x + i, 0, size.x - 1), y), 0).r;
        sum += wy[j] * dot(wx, row);
        if (j == 1 || j == 2) {
            lo = min(lo, min(row.y, row.z));
            hi = max(hi, max(row.y, row.z));
        }
    }
    // The negative lobes overshoot; where the backward map varies from pixel to pixel
    // (converging flow) repeated overshoot can grow without bound. Clamping to the four
    // nearest texels (the bilinear footprint) keeps every frame within its input's range.
    return clamp(sum, lo, hi);
}
#else
float resampleFlow(sampler2D tex, vec2 uv) { return texture(tex, uv).r; }
#endif
