// Overlay, [L] eq. 10: F = beta F_a + (1 - beta) F_s with F_s = colour map x lighting;
// or one of the colour schemes of [W Fig. 6]. Plus texture clipping ([L] Fig. 10:
// opacity 1 over the background) and the optional velocity mask (texture contrast follows
// speed). Display only: never fed back.
layout(binding = 0) uniform sampler2D uFlow;       // F_a or the LIC result I, channel r
layout(binding = 1) uniform sampler2D uDepth;      // 1 = background
layout(binding = 2) uniform sampler2D uShade;      // xyz: eye-space normal, w: speed
layout(binding = 3) uniform sampler2D uColormap;   // 256 x 1 RGBA8
uniform int uScheme;          // OVERLAY_BLEND (eq. 10), OVERLAY_GRAY, ..._GRAY_LIT, ..._HUE_LIT, ..._COOLWARM
uniform float uBeta;          // texture strength
uniform float uContrast;      // display gain of the texture about its mean
uniform float uSpeedMax;      // speed mapped to the top of the colour map
uniform int uUseColormap;     // 0: white surface
uniform int uLighting;
uniform int uVelocityMask;
uniform vec3 uBackground;
out vec4 outColor;

// Diffuse key light above-left of the eye, two-sided (open CFD surfaces).
const vec3 kLight = vec3(-0.35, 0.5, 0.8);
float diffuse(vec3 n) { return abs(dot(n, normalize(kLight))); }

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(uDepth, px, 0).r >= 1.0) {  // texture clipping
        outColor = vec4(uBackground, 1.0);
        return;
    }
    vec4 shade = texelFetch(uShade, px, 0);
    vec3 n = normalize(shade.xyz);
    float speed01 = clamp(shade.w / max(uSpeedMax, 1e-30), 0.0, 1.0);
    float fa = texelFetch(uFlow, px, 0).r;
    float gain = uContrast * (uVelocityMask != 0 ? sqrt(speed01) : 1.0);
    fa = clamp(NOISE_MEAN + (fa - NOISE_MEAN) * gain, 0.0, 1.0);
    float lit = uLighting != 0 ? 0.3 + 0.7 * diffuse(n) : 1.0;
    vec3 color;
    if (uScheme == OVERLAY_GRAY) {
        color = vec3(fa);
    } else if (uScheme == OVERLAY_GRAY_LIT) {
        color = vec3(fa) * (0.3 + 0.7 * diffuse(n));
    } else if (uScheme == OVERLAY_HUE_LIT) {
        vec3 blue = vec3(0.15, 0.3, 0.95), yellow = vec3(1.0, 0.9, 0.2);
        color = mix(blue, yellow, fa) * (0.3 + 0.7 * diffuse(n));
    } else if (uScheme == OVERLAY_COOLWARM) {
        float k = 0.5 * (1.0 + dot(n, normalize(kLight)));  // Gooch: cool facing away, warm towards
        vec3 gooch = mix(vec3(0.25, 0.35, 0.85), vec3(0.95, 0.75, 0.35), k);
        color = vec3(fa) * gooch * 1.2;
    } else {
        vec3 fs = uUseColormap != 0
                      ? texture(uColormap, vec2(speed01 * (255.0 / 256.0) + 0.5 / 256.0, 0.5)).rgb
                      : vec3(1.0);
        color = uBeta * vec3(fa) + (1.0 - uBeta) * fs * lit;
        if (uLighting != 0) color = mix(color, color * lit, 0.5);  // the shape reads through the texture
    }
    outColor = vec4(clamp(color, 0.0, 1.0), 1.0);
}
