// Resampling of the previous F_a at a backward-integrated coordinate [L eq. 12, 13],
// shared by ISA's and IBFVS's texture advection. Default: the texture's bilinear filter,
// as in [L]. Its numerical diffusion (variance a(1-a) px^2 per frame and axis for a
// fractional offset a) blurs across the flow as much as along it, frame after frame.
// RESAMPLE_BICUBIC: Catmull-Rom (4 x 4 texels, interpolating, no gain above 1 at any
// frequency), which keeps features of 4 px period ~0.88 per frame where bilinear keeps
// ~0.71 at the worst offset.
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
    float sum = 0.0;
    for (int j = 0; j < 4; ++j) {
        int y = clamp(i0.y + j, 0, size.y - 1);  // clamp to edge, as the bilinear sampler
        vec4 row;
        for (int i = 0; i < 4; ++i) row[i] = texelFetch(tex, ivec2(clamp(i0.x + i, 0, size.x - 1), y), 0).r;
        sum += wy[j] * dot(wx, row);
    }
    return sum;
}
#else
float resampleFlow(sampler2D tex, vec2 uv) { return texture(tex, uv).r; }
#endif
