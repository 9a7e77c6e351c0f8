// Noise injection and blending, [L] eq. 9: F_a <- (1 - gamma) F_a + gamma G, gamma = alpha
// on the projected surface S' and 0 elsewhere. Applied by each method's advection pass
// right after the resampling (a separate blend pass cost as much again on llvmpipe); the
// caller decides where the surface is. G is that of core/noise.glsl (bilinear cells,
// profile w of k / f_rate + phi_ij) with the phases phi_ij read from a texture.
// NOISE_SWEPT n: G averaged over the segment x - t d', t in [0,1), that the texture at x
// came along in this frame (d' = x - its backward coordinate, pixels): what continuous
// injection along the pathline would deposit; n samples, one per noise cell of the
// largest step (a fixed count: llvmpipe samples textures in a variable loop per pixel).
layout(binding = NOISE_PHASES_UNIT) uniform sampler2D uNoisePhases;  // R32F phi of cell (i, j) at (i, j) + margin
uniform float uPhaseMargin;
uniform uint uFrame;
uniform float uAlpha;   // 0 while the texture is frozen
uniform float uScale;   // s, pixels per cell
uniform float uPeriod;  // f_rate, frames per cycle
uniform int uProfile;   // NOISE_PROFILE_SQUARE or NOISE_PROFILE_SAWTOOTH

// G(x; k), x in pixels, k the frame (a float: k - j may be negative): one gather
// fetches the four cells' phases, (i, j+1), (i+1, j+1), (i+1, j), (i, j).
float noiseGAt(vec2 px, float frame) {
    vec2 u = px / uScale - 0.5;
    vec2 f = floor(u);
    vec2 a = u - f;
    vec4 phi = textureGather(uNoisePhases, (f + 1.0 + uPhaseMargin) / vec2(textureSize(uNoisePhases, 0)));
    vec4 t = fract(frame / uPeriod + phi);
    vec4 g = uProfile == NOISE_PROFILE_SQUARE ? vec4(lessThan(t, vec4(0.5))) : t;
    return mix(mix(g.w, g.z, a.x), mix(g.x, g.y, a.x), a.y);
}

// The G that eq. 9 blends in at `px` in frame `frame`, the pixel having moved by d'.
float injectedG(vec2 px, vec2 motionPx, float frame) {
#ifdef NOISE_SWEPT
    float g = 0.0;
    for (int i = 0; i < NOISE_SWEPT; ++i)
        g += noiseGAt(px - motionPx * ((float(i) + 0.5) / float(NOISE_SWEPT)), frame);
    return g / float(NOISE_SWEPT);
#else
    return noiseGAt(px, frame);
#endif
}

// F_a at fragment `px` after eq. 9, given the resampled F_a `f` and the motion d'.
float injectNoise(float f, vec2 px, vec2 motionPx) {
    if (uAlpha == 0.0) return f;
    return mix(f, injectedG(px, motionPx, float(uFrame)), uAlpha);
}

// What F_a at `px` would hold before this frame's injection had the pixel a full
// upstream history: eq. 9 unrolled, sum_j alpha (1 - alpha)^(j-1) G(px - j d'; k - j),
// along the pathline extended straight upstream with this frame's motion d' (truncated
// at NOISE_HISTORY samples, weights renormalised). A pixel with no usable history (an
// ISA edge point) starts with the contrast and along-flow correlation of the interior.
#define NOISE_HISTORY 24
float noiseHistory(vec2 px, vec2 motionPx, float alpha) {
    float sum = 0.0, wsum = 0.0, w = alpha;
    for (int j = 1; j <= NOISE_HISTORY; ++j, w *= 1.0 - alpha) {
        sum += w * injectedG(px - float(j) * motionPx, motionPx, float(uFrame) - float(j));
        wsum += w;
    }
    return sum / wsum;
}
