// Overlay, [L] eq. 10, shared by overlay.frag and overlay.comp: F = beta F_a + (1 - beta) F_s with F_s = colour map x lighting;
// or one of the colour schemes of [W Fig. 6]. Plus texture clipping ([L] Fig. 10:
// opacity 1 over the background), the optional texture mask (contrast follows speed or
// any scalar, [L] Fig. 13) and the colour legend on top. Display only: never fed back.
layout(binding = OVERLAY_FLOW_UNIT) uniform sampler2D uFlow;           // F_a or the LIC result I, channel r
layout(binding = OVERLAY_DEPTH_UNIT) uniform sampler2D uDepth;         // 1 = background
layout(binding = OVERLAY_SHADE_UNIT) uniform sampler2D uShade;         // xyz: eye-space normal, w: colour value 0..1 (NaN: none)
layout(binding = OVERLAY_COLORMAP_UNIT) uniform sampler2D uColormap;   // 256 x 1 RGBA8
layout(binding = OVERLAY_MASK_UNIT) uniform sampler2D uMaskValue;      // texture mask value 0..1
layout(binding = OVERLAY_LEGEND_UNIT) uniform sampler2D uLegendImage;  // RGBA8, alpha = coverage
// SCHEME (a define per program: OVERLAY_BLEND (eq. 10), OVERLAY_GRAY, ..._GRAY_LIT,
// ..._HUE_LIT, ..._COOLWARM), WITH_LEGEND and WITH_DYE (0 or 1) select the program's
// variant: a software rasteriser runs every branch of a shader, taken or not.
uniform float uBeta;          // texture strength
uniform float uContrast;      // display gain of the texture about its mean
// WITH_COLORMAP (0: white surface), WITH_LIGHTING and WITH_MASK (texture contrast x
// sqrt(mask value)) are program variants, as SCHEME: llvmpipe runs both sides of a branch.
#if WITH_LEGEND
uniform ivec2 uLegendOrigin;  // bottom-left pixel of the legend
#endif
uniform vec3 uBackground;
#if WITH_COLOR_STRETCH
uniform vec2 uLightRange;     // contrast enhancement [doc/contrast.md]: lightness at the stretch's ends
// ... which become these: short of black and white, where a colour map's hue is lost.
const vec2 kLightTarget = vec2(0.08, 0.92);
#endif
#if WITH_DYE
#include "dye/dye_sample.glsl"
uniform int uDyeSlot;         // first value of the current dye
uniform mat4 uInvViewProj;    // window coordinates -> object space, this frame's camera
#endif

// HSL lightness: the mean of the largest and smallest channel.
float lightness(vec3 c) { return 0.5 * (max(c.r, max(c.g, c.b)) + min(c.r, min(c.g, c.b))); }

// `c` with HSL lightness `l`, its hue and saturation kept: every channel is the lightness
// plus the chroma times a pattern of the hue, and the chroma of a saturation scales with
// 1 - |2 l - 1|.
vec3 withLightness(vec3 c, float l) {
    float hi = max(c.r, max(c.g, c.b)), lo = min(c.r, min(c.g, c.b));
    float l0 = 0.5 * (hi + lo), chroma = hi - lo;
    if (chroma <= 1e-6) return vec3(l);
    float saturation = chroma / (1.0 - abs(hi + lo - 1.0));
    float chromaNew = (1.0 - abs(2.0 * l - 1.0)) * saturation;
    return clamp(vec3(l) + (c - vec3(l0)) * (chromaNew / chroma), 0.0, 1.0);
}

// Diffuse key light above-left of the eye, two-sided (open CFD surfaces).
const vec3 kLight = vec3(-0.35, 0.5, 0.8);
float diffuse(vec3 n) { return abs(dot(n, normalize(kLight))); }

vec3 surfaceColor(ivec2 px) {
    vec4 shade = texelFetch(uShade, px, 0);
    vec3 n = normalize(shade.xyz);
    float fa = texelFetch(uFlow, px, 0).r;
#if WITH_MASK
    float gain = uContrast * sqrt(clamp(texelFetch(uMaskValue, px, 0).r, 0.0, 1.0));
#else
    float gain = uContrast;
#endif
    fa = clamp(NOISE_MEAN + (fa - NOISE_MEAN) * gain, 0.0, 1.0);
    float lit = WITH_LIGHTING != 0 ? 0.3 + 0.7 * diffuse(n) : 1.0;
    vec3 color;
    if (SCHEME == OVERLAY_GRAY) {
        color = vec3(fa);
    } else if (SCHEME == OVERLAY_GRAY_LIT) {
        color = vec3(fa) * (0.3 + 0.7 * diffuse(n));
    } else if (SCHEME == OVERLAY_HUE_LIT) {
        vec3 blue = vec3(0.15, 0.3, 0.95), yellow = vec3(1.0, 0.9, 0.2);
        color = mix(blue, yellow, fa) * (0.3 + 0.7 * diffuse(n));
    } else if (SCHEME == OVERLAY_COOLWARM) {
        float k = 0.5 * (1.0 + dot(n, normalize(kLight)));  // Gooch: cool facing away, warm towards
        vec3 gooch = mix(vec3(0.25, 0.35, 0.85), vec3(0.95, 0.75, 0.35), k);
        color = vec3(fa) * gooch * 1.2;
    } else {
        float value01 = clamp(shade.w, 0.0, 1.0);
        vec3 fs = WITH_COLORMAP == 0 ? vec3(1.0)
                  : isnan(shade.w)  ? vec3(0.5)  // no value here (array missing on this patch)
                                    : textureLod(uColormap, vec2(value01 * (255.0 / 256.0) + 0.5 / 256.0, 0.5), 0.0).rgb;
        color = uBeta * vec3(fa) + (1.0 - uBeta) * fs * lit;
        if (WITH_LIGHTING != 0) color = mix(color, color * lit, 0.5);  // the shape reads through the texture
    }
    return clamp(color, 0.0, 1.0);
}

#if WITH_DYE
// Dye [doc/algorithms.md §10] over the surface colour: sampled in object space at the visible surface
// point of the pixel (depth unprojected), so only what the camera sees shows dye.
vec3 withDye(vec3 color, ivec2 px, float depth) {
    vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 p = uInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    vec4 d = clamp(sampleDye(p.xyz / p.w, uDyeSlot), 0.0, 1.0);  // premultiplied
    float lit = WITH_LIGHTING != 0 ? 0.55 + 0.45 * diffuse(normalize(texelFetch(uShade, px, 0).xyz)) : 1.0;
    return color * (1.0 - d.a) + d.rgb * lit;
}
#endif

// The displayed colour of pixel `px`.
vec3 overlayColor(ivec2 px) {
    float depth = texelFetch(uDepth, px, 0).r;
    vec3 color = depth >= 1.0 ? uBackground  // texture clipping
                              : surfaceColor(px);
#if WITH_COLOR_STRETCH
    if (depth < 1.0)
        color = withLightness(color, mix(kLightTarget.x, kLightTarget.y,
                                         clamp((lightness(color) - uLightRange.x) / (uLightRange.y - uLightRange.x), 0.0, 1.0)));
#endif
#if WITH_DYE
    if (depth < 1.0) color = clamp(withDye(color, px, depth), 0.0, 1.0);
#endif
#if WITH_LEGEND
    {
        ivec2 q = px - uLegendOrigin;
        if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, textureSize(uLegendImage, 0)))) {
            vec4 l = texelFetch(uLegendImage, q, 0);
            color = mix(color, l.rgb, l.a);
        }
    }
#endif
    return color;
}
