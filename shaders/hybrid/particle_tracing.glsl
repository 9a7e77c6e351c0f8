// Hybrid steps 2-5, particle tracing and LIC accumulation [W §3-5, eqs. 2, 3, 5]: the
// loop of one pixel, licAt(), shared by the fragment (particle_tracing.frag) and the
// compute (particle_tracing.comp) passes. The particle moves in P-space (eq. 3) with the
// velocity read from the D-space texture at its projection (eq. 2); positions are never
// projected back onto the surface. A particle stops where its projection leaves the
// surface or its depth disagrees with the visible layer (it went behind an occluder, or
// off an edge), so no streak crosses an occluding edge. For unsteady flow (UNSTEADY) each
// step also advances the particle's data time, and the velocity is read from the image of
// that time: pathlines instead of streamlines.
// What the loop needs of the position is affine in it: the clip coordinates (projection),
// the noise coordinates and the layer depth. The loop carries those three instead and
// moves them through per-pixel step maps (the step length folded in), and it reads no
// uniform: llvmpipe reads a uniform inside divergent control flow with one load per lane.
#include "hybrid/kernels.glsl"
layout(binding = LIC_SEED_VELOCITY_UNIT) uniform sampler2D uSeedVelocity;  // the velocity image, nearest: w = layer depth, 0 off the surface
#ifdef UNSTEADY
// Unsteady flow [W §3]: the velocity image per time level, layer j at data time
// uLevelTime[j] after the frame's (divided by the reference speed, uVelocityScale); the
// trilinear lookup is linear in time between levels.
layout(binding = LIC_VELOCITY_UNIT) uniform sampler3D uVelLevels;
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
layout(binding = LIC_VELOCITY_UNIT) uniform sampler2D uVelObj;    // RGBA32F tangential velocity, linear
#endif
// The solid noise, RGBA8 2 x 2 neighbourhoods (solid_noise.comp), read as an image: a
// texelFetch would look up its mip level per lane.
layout(binding = LIC_NOISE_IMAGE_UNIT, rgba8) readonly uniform image3D uNoise;
uniform mat4 uTexFromObj;     // P-space -> image texture coordinates (x, y, -, w): eq. 2
// The ray through a pixel: P = origin + s dir with, at normalised device coordinates n,
// perspective: origin = uEye, dir = uForward + n.x uRayRight + n.y uRayUp; orthographic:
// origin = uEye + n.x uRayRight + n.y uRayUp, dir = uForward.
uniform vec3 uForward;
uniform vec3 uRayRight;
uniform vec3 uRayUp;
uniform vec4 uLayerDepthRow;  // layer depth of a P-space point (methods::layerDepthRow)
uniform vec3 uEye;
uniform int uOrtho;
uniform int uFilterLength;   // L = 2 * half + 1 samples
uniform float uStepPerDist;  // P-space step per unit of distance to the eye (dt ~ d)
uniform float uStepOrtho;    // P-space step for orthographic views
uniform float uFreqAtUnit;   // noise texels per P-space unit at distance 1 (ortho: absolute)
uniform float uDepthTolerance;  // fraction of the depth range
#ifdef ORIENTED
uniform float uInvDropSamples;  // 1 / the samples a lone drop covers along a streamline
#endif
// Compile-time choices (program variants; a uniform branch per step halves the speed on
// llvmpipe): KERNEL one of KERNEL_BOX .. KERNEL_HANN; INTEGRATOR one of INTEGRATOR_EULER,
// INTEGRATOR_RK2 (midpoint), INTEGRATOR_RK4; LINE_FIELD 1 for vectors without sign
// (principal directions): each sample is turned to agree with the particle's previous
// step, so a streamline never folds back at a sign flip. ORIENTED: oriented LIC, the
// sparse solid noise under a one-sided kernel (orientedWeight in kernels.glsl).

// A P-space displacement d mapped to the particle's clip coordinates, noise coordinates
// and layer depth (times the step length h: d = h v for a velocity v).
struct StepMap {
    mat3 clip;
    mat3 noise;
    vec3 depth;
    float invTolerance;  // 1 / the depth tolerance
};
// The velocity image at image point s and data time t after the frame's (steady: t unused).
vec4 velocityImage(vec2 s, float t) {
#ifdef UNSTEADY
    return texture(uVelLevels, vec3(s, (levelOf(t) + 0.5) / float(uLevelCount)));
#else
    return texture(uVelObj, s);
#endif
}
// Velocity at the particle (clip coordinates c, layer depth d) and its data time t after
// the frame's (unused for steady flow); false where it is off the visible surface: its
// projection leaves the image, or its depth differs from the visible layer's there (the
// image's w; 0 on the background, and a blend of both sides within a pixel of an edge).
// One exit, no early return: llvmpipe pays for each return inside the loop with an extra
// execution mask; the lookup outside the image is clamped and discarded.
bool velocityAt(vec3 c, float d, float t, vec3 ref, float invTolerance, out vec3 v) {
    vec2 s = c.xy / c.z;
    vec4 vel = velocityImage(s, t);
    v = vel.xyz;
#if LINE_FIELD
    if (dot(v, ref) < 0.0) v = -v;
#endif
    return all(greaterThanEqual(s, vec2(0.0))) && all(lessThanEqual(s, vec2(1.0))) &&
           abs(d - vel.w) * invTolerance <= 1.0;
}
// The velocity v of one step from data time t to t + dt (a pathline through unsteady
// data; dt = 0 for steady flow): the integrator's stages are taken through the step map.
// False if any stage is off the surface (one exit, as velocityAt).
bool stepVelocity(vec3 c, float d, StepMap m, float t, float dt, inout vec3 ref, out vec3 v) {
    vec3 k1, k2, k3, k4;
    bool on = velocityAt(c, d, t, ref, m.invTolerance, k1);
    ref = k1;
    v = k1;
    if (INTEGRATOR == INTEGRATOR_EULER) return on;
    on = velocityAt(c + 0.5 * (m.clip * k1), d + 0.5 * dot(m.depth, k1), t + 0.5 * dt, ref, m.invTolerance, k2) && on;
    v = k2;
    if (INTEGRATOR == INTEGRATOR_RK2) return on;
    on = velocityAt(c + 0.5 * (m.clip * k2), d + 0.5 * dot(m.depth, k2), t + 0.5 * dt, ref, m.invTolerance, k3) && on;
    on = velocityAt(c + m.clip * k3, d + dot(m.depth, k3), t + dt, ref, m.invTolerance, k4) && on;
    v = (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    return on;
}
// A fixed oblique rotation of the lookup: flat data lying in an axis plane (a CFD slice)
// would otherwise sample the lattice along a texel plane and show its grid.
// 0.7 rad about (1, 2, 3), columns.
const mat3 kNoiseRotation = mat3(0.781639, 0.550117, -0.293958,
                                 -0.482929, 0.832030, 0.272956,
                                 0.394740, -0.071392, 0.916015);
// The wrapped solid noise's code at texture coordinates q, trilinear as GL filters it: the
// texel at the lower corner holds the 2 x 2 neighbourhood in x and y (solid_noise.comp),
// so two fetches (z and z + 1) cover the eight corners.
float noiseTrilinear(vec3 q) {
    vec3 p = q * float(NOISE_SIZE) - 0.5;
    vec3 i = floor(p);
    vec3 t = p - i;
    ivec3 c = ivec3(i) & (NOISE_SIZE - 1);
    vec4 a = imageLoad(uNoise, c);
    vec4 b = imageLoad(uNoise, ivec3(c.xy, (c.z + 1) & (NOISE_SIZE - 1)));
    vec4 m = mix(a, b, t.z);        // (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)
    vec2 r = mix(m.xz, m.yw, t.x);  // rows y and y + 1
    return mix(r.x, r.y, t.y);
}
// Constant image-space frequency [W §5]: two octave-snapped scales mixed by the
// fractional part f of log2 of the seed's distance. q: the finer octave's coordinates;
// the coarser one's are q * coarse (1/2; orthographic views: 1, f = 0).
float noiseAt(vec3 q, float coarse, float f) {
    return mix(noiseTrilinear(q), noiseTrilinear(q * coarse), f);
}

// The seed: the visible surface point of pixel px, on the ray through the pixel centre
// where the layer depth (affine in P-space) takes the velocity image's value w there.
vec3 seedPosition(ivec2 px, float w) {
    vec2 n = (vec2(px) + 0.5) / vec2(textureSize(uSeedVelocity, 0)) * 2.0 - 1.0;
    vec3 across = n.x * uRayRight + n.y * uRayUp;
    vec3 origin = uOrtho != 0 ? uEye + across : uEye;
    vec3 dir = uOrtho != 0 ? uForward : uForward + across;
    return origin + dir * ((w - dot(uLayerDepthRow, vec4(origin, 1.0))) / dot(uLayerDepthRow.xyz, dir));
}

// The LIC value I of pixel px; false off the surface (background pixels do no work).
bool licAt(ivec2 px, out float result) {
    float layer = texelFetch(uSeedVelocity, px, 0).w;
    if (layer < 0.5) return false;
    vec4 seed = vec4(seedPosition(px, layer), 1.0);
    float dist = length(seed.xyz - uEye);
    float fineFreq = uFreqAtUnit, coarse = 1.0, f = 0.0;
    if (uOrtho == 0) {
        float l = log2(max(dist, 1e-6));
        f = fract(l);
        fineFreq = uFreqAtUnit * exp2(-floor(l));
        coarse = 0.5;
    }
    float h = uOrtho != 0 ? uStepOrtho : uStepPerDist * dist;
    vec3 clip0 = (uTexFromObj * vec4(seed.xyz, 1.0)).xyw;
    vec3 noise0 = kNoiseRotation * seed.xyz * fineFreq;
    float depth0 = dot(uLayerDepthRow, vec4(seed.xyz, 1.0));
    mat3 clipOfObj = mat3(uTexFromObj[0].xyw, uTexFromObj[1].xyw, uTexFromObj[2].xyw);
    float invTolerance = 1.0 / uDepthTolerance;
    int halfLength = (uFilterLength - 1) / 2;
    float du = 1.0 / float(halfLength + 1);
#ifdef UNSTEADY
    float dt = uTimePerStep;
    float velocityScale = uVelocityScale;
#else
    float dt = 0.0;
    float velocityScale = 1.0;
#endif
#ifdef ORIENTED
    float lic = orientedWeight(0.5) * noiseAt(noise0, coarse, f);  // the seed: mid-streak
#else
    float lic = noiseAt(noise0, coarse, f), weight = 1.0;  // k(0) = 1
#endif
    vec3 ref0 = velocityImage(clip0.xy / clip0.z, 0.0).xyz;  // both halves start along the seed's vector
    for (int dir = -1; dir <= 1; dir += 2) {  // backward and forward halves
        float hs = float(dir) * h * velocityScale;
        StepMap m = StepMap(clipOfObj * hs, kNoiseRotation * (fineFreq * hs), uLayerDepthRow.xyz * hs,
                                  invTolerance);
        vec3 c = clip0, q = noise0, ref = ref0;
        float d = depth0;
#ifndef ORIENTED
        KernelWalk k = kernelWalk(du);
#endif
        for (int i = 1; i <= halfLength; ++i) {
            // Step i runs from data time (i - 1) dt to i dt, backward in time for dir < 0.
            vec3 v;
            if (!stepVelocity(c, d, m, float(dir * (i - 1)) * dt, float(dir) * dt, ref, v)) break;
            c += m.clip * v;
            q += m.noise * v;
            d += dot(m.depth, v);
#ifdef ORIENTED
            lic += orientedWeight(0.5 + 0.5 * float(dir * i) * du) * noiseAt(q, coarse, f);
#else
            kernelNext(k);
            lic += k.weight * noiseAt(q, coarse, f);
            weight += k.weight;
#endif
        }
    }
#ifdef ORIENTED
    // Not normalised by the weights: a drop met over 1 / uInvDropSamples samples at the head's
    // weight gives 1, the streak behind it the kernel's falloff; the ground (no drop, 0) and
    // a full head (1) land at the ends of the overlay's contrast about the noise mean.
    result = NOISE_MEAN + DROP_SPREAD * (2.0 * min(lic * uInvDropSamples, 1.0) - 1.0);
#else
    result = 0.5 + (lic / weight - 0.5) * (1.0 / NOISE_CODE);  // the code's average, decoded
#endif
    return true;
}
