// Dye advection [doc/algorithms.md §10], one invocation per band voxel x; the closest point method
// [Ruuth & Merriman 2008] with MacCormack [Selle et al. 2008]. Pass 0 (forward step):
// u^(x) = u(cp(x) - v dt). Pass 1: u'(x) = u^(x) + (u(x) - u^(cp(x) + v dt)) / 2, clamped
// to the extremes of u around cp(x) - v dt. Pass 3: the departure points of passes 0 and 1
// (each step taken along the surface: departure()), when velocity or dt change. (pass 2: u' = u, no motion), decayed, then
// this frame's emitters. Pass 4: u^ back to 0 where pass 0 wrote it, so that between steps
// u^ is 0 wherever a pass 1 reads it without this step's pass 0 having written it (the same
// on one process and on several that each advect a part, dye_shared.h).
// Dye below kDyeVisible is cleared: a brick without a flag holds none, so the processes
// that advect parts of the band exchange only flagged bricks.
// Values: RGBA32F premultiplied, slots of the band's size in one buffer.
#include "dye/dye_sample.glsl"
layout(local_size_x = DYE_GROUP) in;
struct BandVoxel { vec4 closest; vec4 velocity; };  // object space, w: brick; velocity per data time
layout(std430, binding = DYE_BAND_BINDING) readonly buffer Band { BandVoxel band[]; };
struct Emitter { vec4 posRadius; vec4 color; };
layout(std430, binding = DYE_SOURCE_BINDING) readonly buffer Emitters { Emitter emitter[]; };
// Per band voxel: the departure points cp - v dt and cp + v dt along the surface (pass 3),
// kept while velocity and dt stay (every frame of steady data).
layout(std430, binding = DYE_DEPARTURE_BINDING) buffer Departures { vec4 departurePoint[]; };
// The band voxels this step updates (bricks holding dye and those it can reach), and per
// brick a flag set where the step leaves dye.
layout(std430, binding = DYE_ACTIVE_BINDING) readonly buffer Active { uint activeVoxel[]; };
layout(std430, binding = DYE_FLAG_BINDING) writeonly buffer Flags { uint hasDye[]; };
uniform int uPass;
uniform int uUseList;     // 1: invocation g updates activeVoxel[g]; 0: band voxel g
uniform int uCount;       // invocations
uniform int uSource;      // slot of u
uniform int uForward;     // slot of u^
uniform int uTarget;      // slot written
uniform float uDt;        // data time of this frame
uniform float uDecay;     // exp(-decay dt)
uniform int uEmitters;

// The surface point near x: closest points of the grid cells around x, trilinear.
vec3 closestNear(vec3 x) {
    vec3 g = (x - uDyeOrigin) / uDyeH - 0.5;
    ivec3 base = ivec3(floor(g));
    vec3 f = g - vec3(base);
    vec4 sum = vec4(0.0);
    for (int k = 0; k < 8; ++k) {
        ivec3 c = base + ivec3(k & 1, (k >> 1) & 1, k >> 2);
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, textureSize(uDyeIndex, 0)))) continue;
        int i = texelFetch(uDyeIndex, c, 0).r;
        if (i < 0) continue;
        vec3 w3 = mix(1.0 - f, f, vec3(c - base));
        float w = w3.x * w3.y * w3.z;
        sum += vec4(band[i].closest.xyz * w, w);
    }
    return sum.w > 0.0 ? sum.xyz / sum.w : x;
}

// Where the ink at cp came from, `step` = v dt away along the surface: the straight step
// turned into a chord of the surface of the same length (a straight tangent step lands
// short by |step|^3 k^2 / 3 on a surface of curvature k; the chord by a sixteenth of that).
vec3 departure(vec3 cp, vec3 step) {
    float len = length(step);
    vec3 chord = closestNear(cp - step) - cp;
    float c = length(chord);
    return c > 1e-3 * len ? cp + chord * (len / c) : cp - step;
}

void main() {
    int g = int(gl_GlobalInvocationID.x);
    if (g >= uCount) return;
    int i = uUseList != 0 ? int(activeVoxel[g]) : g;
    vec3 cp = band[i].closest.xyz;
    if (uPass == 4) {
        dyeValue[uForward + i] = vec4(0.0);
        return;
    }
    if (uPass == 3) {
        vec3 step = band[i].velocity.xyz * uDt;
        departurePoint[2 * i] = vec4(departure(cp, step), 0.0);
        departurePoint[2 * i + 1] = vec4(departure(cp, -step), 0.0);
        return;
    }
    if (uPass == 0) {
        dyeValue[uForward + i] = sampleDye(departurePoint[2 * i].xyz, uSource);
        return;
    }
    vec4 u = dyeValue[uSource + i];  // pass 2: no motion this frame
    if (uPass == 1) {
        vec4 lo, hi;
        sampleDye(departurePoint[2 * i].xyz, uSource, lo, hi);
        u = clamp(dyeValue[uForward + i] + 0.5 * (u - sampleDye(departurePoint[2 * i + 1].xyz, uForward)), lo, hi);
    }
    u *= uDecay;
    for (int e = 0; e < uEmitters; ++e) {
        float r = emitter[e].posRadius.w;
        // Full strength inside, a one-cell ramp at the rim (no staircase of voxels).
        float a = clamp((r - distance(cp, emitter[e].posRadius.xyz)) / uDyeH + 0.5, 0.0, 1.0);
        u = mix(u, vec4(emitter[e].color.rgb, 1.0), a);
    }
    const bool visible = max(max(u.r, u.g), max(u.b, u.a)) > DYE_VISIBLE;
    dyeValue[uTarget + i] = visible ? u : vec4(0.0);
    if (visible) hasDye[int(band[i].closest.w)] = 1u;
}
