// Hybrid steps 2-5, particle tracing and LIC accumulation [W §3-5, eqs. 2, 3, 5]: the
// loop of one pixel, licAt(), shared by the fragment (particle_tracing.frag) and the
// compute (particle_tracing.comp) passes. The particle's P-space position is projected (eq. 2), the
// velocity is read from the D-space texture there, and the step is taken in P-space
// (eq. 3); positions are never projected back onto the surface. A particle stops where
// its projection leaves the surface or its depth disagrees with the visible layer (it
// went behind an occluder, or off an edge), so no streak crosses an occluding edge.
// For unsteady flow (UNSTEADY) each step also advances the particle's data time, and the
// velocity is read from the image of that time: pathlines instead of streamlines.
#include "hybrid/kernels.glsl"
layout(binding = 0) uniform sampler2D uPosObj;    // RGBA32F seed positions, w = coverage
#ifdef UNSTEADY
// Unsteady flow [W §3]: the velocity image per time level, layer j at data time
// uLevelTime[j] after the frame's (divided by the reference speed); the trilinear lookup
// is linear in time between levels.
layout(binding = 1) uniform sampler3D uVelLevels;
uniform int uLevelCount;
uniform float uLevelTime[MAX_LEVELS];  // increasing
uniform float uTimePerStep;
uniform float uVelocityScale;
// Level coordinate (j + fraction) of data time t after the frame's, held at the ends.
float levelOf(float t) {
    if (t <= uLevelTime[0]) return 0.0;
    for (int j = 1; j < uLevelCount; ++j)
        if (t <= uLevelTime[j]) return float(j - 1) + (t - uLevelTime[j - 1]) / (uLevelTime[j] - uLevelTime[j - 1]);
    return float(uLevelCount - 1);
}
#else
layout(binding = 1) uniform sampler2D uVelObj;    // RGBA32F tangential velocity, linear
#endif
layout(binding = 3) uniform sampler3D uNoise;     // solid noise, wrapped, trilinear
uniform mat4 uViewProj;
uniform vec4 uLayerDepthRow;  // layer depth of a P-space point (methods::layerDepthRow)
uniform vec3 uEye;
uniform int uOrtho;
uniform int uHalfLength;     // steps per half: L = 2 * half + 1 samples
// Compile-time choices (program variants; a uniform branch per step halves the speed on
// llvmpipe): KERNEL one of KERNEL_BOX .. KERNEL_HANN; INTEGRATOR one of INTEGRATOR_EULER,
// INTEGRATOR_RK2 (midpoint), INTEGRATOR_RK4.
const int uKernel = KERNEL;
const int uIntegrator = INTEGRATOR;
uniform float uStepPerDist;  // P-space step per unit of distance to the eye (dt ~ d)
uniform float uStepOrtho;    // P-space step for orthographic views
uniform float uFreqAtUnit;   // noise texels per P-space unit at distance 1 (ortho: absolute)
uniform float uDepthTolerance;  // fraction of the depth range

// Device coordinates of p in [0, 1]^2.
vec2 project(vec3 p) {
    vec4 c = uViewProj * vec4(p, 1.0);
    return c.xy / c.w * 0.5 + 0.5;
}
// The velocity image at device point s and the particle's data time t after the frame's
// (unused for steady flow).
vec4 velocityImage(vec2 s, float t) {
#ifdef UNSTEADY
    float z = (levelOf(t) + 0.5) / float(uLevelCount);
    return texture(uVelLevels, vec3(s, z)) * vec4(vec3(uVelocityScale), 1.0);
#else
    return texture(uVelObj, s);
#endif
}
// Velocity at the projection of p; false where p is off the visible surface: its depth
// differs from the visible layer's there (the image's w; 0 on the background, and a blend
// of both sides within a pixel of an edge).
// A line field (principal directions: no sign): each sample is turned to agree with the
// particle's previous step `ref`, so a streamline never folds back at a sign flip.
uniform int uLineField;
bool velocityAt(vec3 p, float t, vec3 ref, out vec3 v) {
    vec2 s = project(p);
    if (any(lessThan(s, vec2(0.0))) || any(greaterThan(s, vec2(1.0)))) return false;
    vec4 vel = velocityImage(s, t);
    if (abs(dot(uLayerDepthRow, vec4(p, 1.0)) - vel.w) > uDepthTolerance) return false;
    v = vel.xyz;
    if (uLineField != 0 && dot(v, ref) < 0.0) v = -v;
    return true;
}
// One step of length h from data time t to t + dt (a pathline through unsteady data;
// dt = 0 for steady flow).
bool stepParticle(inout vec3 p, float h, float t, float dt, inout vec3 ref) {
    vec3 k1, k2, k3, k4;
    if (!velocityAt(p, t, ref, k1)) return false;
    ref = k1;
    if (uIntegrator == INTEGRATOR_EULER) { p += h * k1; return true; }
    if (!velocityAt(p + 0.5 * h * k1, t + 0.5 * dt, ref, k2)) return false;
    if (uIntegrator == INTEGRATOR_RK2) { p += h * k2; return true; }
    if (!velocityAt(p + 0.5 * h * k2, t + 0.5 * dt, ref, k3)) return false;
    if (!velocityAt(p + h * k3, t + dt, ref, k4)) return false;
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

// The LIC value I of pixel px; false off the surface (background pixels do no work).
bool licAt(ivec2 px, out float result) {
    vec4 seed = texelFetch(uPosObj, px, 0);
    if (seed.w < 0.5) return false;
    float dist = length(seed.xyz - uEye);
    float f;
    vec2 scales = octaveScales(dist, f);
    float h = uOrtho != 0 ? uStepOrtho : uStepPerDist * dist;
    float weight = kernelWeight(uKernel, 0.0);
    float lic = weight * noiseAt(seed.xyz, scales, f);
#ifdef UNSTEADY
    float dt = uTimePerStep;
#else
    float dt = 0.0;
#endif
    for (int dir = -1; dir <= 1; dir += 2) {  // backward and forward halves
        vec3 p = seed.xyz;
        vec3 ref = velocityImage(project(p), 0.0).xyz;  // both halves start along the seed's vector
        for (int i = 1; i <= uHalfLength; ++i) {
            // Step i runs from data time (i - 1) dt to i dt, backward in time for dir < 0.
            if (!stepParticle(p, float(dir) * h, float(dir * (i - 1)) * dt, float(dir) * dt, ref)) break;
            float k = kernelWeight(uKernel, float(i) / float(uHalfLength + 1));
            lic += k * noiseAt(p, scales, f);
            weight += k;
        }
    }
    result = lic / weight;
    return true;
}
