// Overlay, [L] eq. 10: F = beta F_a + (1 - beta) F_s with F_s = colour map x lighting;
// plus texture clipping ([L] Fig. 10: opacity 1 over the background) and the optional
// velocity mask (texture contrast follows speed). Display only: never fed back.
layout(binding = 0) uniform sampler2D uFlow;       // F_a, channel r
layout(binding = 1) uniform sampler2D uDepth;      // 1 = background
layout(binding = 2) uniform sampler2D uShade;      // xyz: eye-space normal, w: speed
layout(binding = 3) uniform sampler2D uColormap;   // 256 x 1 RGBA8
uniform float uBeta;          // texture strength
uniform float uContrast;      // display gain of F_a about its mean
uniform float uFlowMean;      // mean of F_a (the noise mean)
uniform float uSpeedMax;      // speed mapped to the top of the colour map
uniform int uUseColormap;     // 0: white surface
uniform int uLighting;
uniform int uVelocityMask;
uniform vec3 uBackground;
out vec4 outColor;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(uDepth, px, 0).r >= 1.0) {  // texture clipping
        outColor = vec4(uBackground, 1.0);
        return;
    }
    vec4 shade = texelFetch(uShade, px, 0);
    float speed01 = clamp(shade.w / max(uSpeedMax, 1e-30), 0.0, 1.0);
    float fa = texelFetch(uFlow, px, 0).r;
    float gain = uContrast * (uVelocityMask != 0 ? sqrt(speed01) : 1.0);
    fa = clamp(uFlowMean + (fa - uFlowMean) * gain, 0.0, 1.0);
    vec3 fs = uUseColormap != 0 ? texture(uColormap, vec2(speed01 * (255.0 / 256.0) + 0.5 / 256.0, 0.5)).rgb
                                : vec3(1.0);
    float light = 1.0;
    if (uLighting != 0) {
        vec3 n = normalize(shade.xyz);
        // A key light above-left of the eye, two-sided (open CFD surfaces).
        light = 0.3 + 0.7 * abs(dot(n, normalize(vec3(-0.35, 0.5, 0.8))));
    }
    vec3 color = uBeta * vec3(fa) + (1.0 - uBeta) * fs * light;
    // Lighting also shades the texture so the shape reads through it.
    if (uLighting != 0) color = mix(color, color * light, 0.5);
    outColor = vec4(color, 1.0);
}
