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
    vec2 size = vec2(textureSize(tex, 0));
    vec2 p = uv * size - 0.5;  // texel-centre coordinates
    vec2 base = floor(p);
    vec2 t = p - base;
    vec4 wx = catmullRomWeights(t.x), wy = catmullRomWeights(t.y);
    // The 4 x 4 footprint as four 2 x 2 gathers (clamp to edge from the sampler). A
    // gather at the corner shared by texels (i, j)..(i+1, j+1) returns
    // (i, j+1), (i+1, j+1), (i+1, j), (i, j).
    vec2 c = (base + 0.0) / size;  // corner between texels base-1 and base
    vec2 s2 = 2.0 / size;
    vec4 g00 = textureGather(tex, c), g10 = textureGather(tex, c + vec2(s2.x, 0.0));
    vec4 g01 = textureGather(tex, c + vec2(0.0, s2.y)), g11 = textureGather(tex, c + s2);
    vec4 r0 = vec4(g00.wz, g10.wz), r1 = vec4(g00.xy, g10.xy);
    vec4 r2 = vec4(g01.wz, g11.wz), r3 = vec4(g01.xy, g11.xy);
    float sum = dot(wy, vec4(dot(wx, r0), dot(wx, r1), dot(wx, r2), dot(wx, r3)));
    // The negative lobes overshoot; where the backward map varies from pixel to pixel
    // (converging flow) repeated overshoot can grow without bound. Clamping to the four
    // nearest texels (the bilinear footprint) keeps every frame within its input's range.
    float lo = min(min(r1.y, r1.z), min(r2.y, r2.z)), hi = max(max(r1.y, r1.z), max(r2.y, r2.z));
    return clamp(sum, lo, hi);
}
#else
float resampleFlow(sampler2D tex, vec2 uv) { return textureLod(tex, uv, 0.0).r; }
#endif
