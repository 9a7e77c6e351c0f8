// Hybrid steps 2-5, particle tracing and LIC accumulation [W §3-5, eqs. 2, 3, 5], one
// pass with a loop per pixel: the particle's P-space position is projected (eq. 2), the
// velocity is read from the D-space texture there, and the step is taken in P-space
// (eq. 3); positions are never projected back onto the surface. A particle stops where
// its projection leaves the surface or its depth disagrees with the visible layer (it
// went behind an occluder, or off an edge), so no streak crosses an occluding edge.
#include "hybrid/kernels.glsl"
layout(binding = 0) uniform sampler2D uPosObj;    // RGBA32F seed positions, w = coverage
layout(binding = 1) uniform sampler2D uVelObj;    // RGBA32F tangential velocity, linear
layout(binding = 2) uniform sampler2D uDepth;     // window depth of the visible layer
layout(binding = 3) uniform sampler3D uNoise;     // solid noise, wrapped, trilinear
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform int uOrtho;
uniform float uNear;
uniform float uFar;
uniform int uHalfLength;     // steps per half: L = 2 * half + 1 samples
uniform int uKernel;
uniform int uIntegrator;     // 0 Euler, 1 RK2 (midpoint), 2 RK4
uniform float uStepPerDist;  // P-space step per unit of distance to the eye (dt ~ d)
uniform float uStepOrtho;    // P-space step for orthographic views
uniform float uFreqAtUnit;   // noise texels per P-space unit at distance 1 (ortho: absolute)
uniform float uDepthTolerance;
out vec4 outLic;

vec3 project(vec3 p) {
    vec4 c = uViewProj * vec4(p, 1.0);
    return vec3(c.xy / c.w * 0.5 + 0.5, c.z / c.w * 0.5 + 0.5);
}
float linearDepth(float d) {
    return uOrtho != 0 ? uNear + d * (uFar - uNear) : uNear * uFar / (uFar - d * (uFar - uNear));
}
// Velocity at the projection of p; false where p is off the visible surface.
bool velocityAt(vec3 p, out vec3 v) {
    vec3 s = project(p);
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return false;
    vec4 vel = texture(uVelObj, s.xy);
    if (vel.w < 0.5) return false;
    float visible = texture(uDepth, s.xy).r;
    if (abs(linearDepth(s.z) - linearDepth(visible)) > uDepthTolerance) return false;
    v = vel.xyz / vel.w;
    return true;
}
bool stepParticle(inout vec3 p, float h) {
    vec3 k1, k2, k3, k4;
    if (!velocityAt(p, k1)) return false;
    if (uIntegrator == 0) { p += h * k1; return true; }
    if (!velocityAt(p + 0.5 * h * k1, k2)) return false;
    if (uIntegrator == 1) { p += h * k2; return true; }
    if (!velocityAt(p + 0.5 * h * k2, k3)) return false;
    if (!velocityAt(p + h * k3, k4)) return false;
    p += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    return true;
}
// Constant image-space frequency [W §5]: two octave-snapped scales mixed by the
// fractional part of log2 of the seed's distance.
vec2 octaveScales(float dist, out float f) {
    if (uOrtho != 0) { f = 0.0; return vec2(uFreqAtUnit); }
    float l = log2(max(dist, 1e-6));
    float i = floor(l);
    f = l - i;
    return uFreqAtUnit * vec2(exp2(-i), exp2(-(i + 1.0)));
}
// A fixed oblique rotation of the lookup: flat data lying in an axis plane (a CFD slice)
// would otherwise sample the lattice along a texel plane and show its grid.
// 0.7 rad about (1, 2, 3), columns.
const mat3 kNoiseRotation = mat3(0.781639, 0.550117, -0.293958,
                                 -0.482929, 0.832030, 0.272956,
                                 0.394740, -0.071392, 0.916015);
float noiseAt(vec3 p, vec2 scales, float f) {
    vec3 q = kNoiseRotation * p;
    return mix(texture(uNoise, q * scales.x).r, texture(uNoise, q * scales.y).r, f);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 seed = texelFetch(uPosObj, px, 0);
    if (seed.w < 0.5) discard;  // background pixels do no work
    float dist = length(seed.xyz - uEye);
    float f;
    vec2 scales = octaveScales(dist, f);
    float h = uOrtho != 0 ? uStepOrtho : uStepPerDist * dist;
    float weight = kernelWeight(uKernel, 0.0);
    float lic = weight * noiseAt(seed.xyz, scales, f);
    for (int dir = -1; dir <= 1; dir += 2) {  // backward and forward halves
        vec3 p = seed.xyz;
        for (int i = 1; i <= uHalfLength; ++i) {
            if (!stepParticle(p, float(dir) * h)) break;
            float k = kernelWeight(uKernel, float(i) / float(uHalfLength + 1));
            lic += k * noiseAt(p, scales, f);
            weight += k;
        }
    }
    outLic = vec4(lic / weight, 0.0, 0.0, 1.0);
}
