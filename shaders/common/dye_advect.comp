// Dye advection [issue 20], one invocation per band voxel x; the closest point method
// [Ruuth & Merriman 2008] with MacCormack [Selle et al. 2008]. Pass 0 (forward step):
// u^(x) = u(cp(x) - v dt). Pass 1: u'(x) = u^(x) + (u(x) - u^(cp(x) + v dt)) / 2, clamped
// to the extremes of u around cp(x) - v dt (pass 2: u' = u, no motion), decayed, then
// this frame's emitters.
// Values: RGBA32F premultiplied, slots of the band's size in one buffer.
#include "common/dye_sample.glsl"
layout(local_size_x = DYE_GROUP) in;
struct BandVoxel { vec4 closest; vec4 velocity; };  // object space; velocity per data time
layout(std430, binding = DYE_BAND_BINDING) readonly buffer Band { BandVoxel band[]; };
struct Emitter { vec4 posRadius; vec4 color; };
layout(std430, binding = DYE_SOURCE_BINDING) readonly buffer Emitters { Emitter emitter[]; };
uniform int uPass;
uniform int uCount;       // band voxels
uniform int uSource;      // slot of u
uniform int uForward;     // slot of u^
uniform int uTarget;      // slot written
uniform float uDt;        // data time of this frame
uniform float uDecay;     // exp(-decay dt)
uniform int uEmitters;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec3 cp = band[i].closest.xyz;
    vec3 step = band[i].velocity.xyz * uDt;
    if (uPass == 0) {
        dyeValue[uForward + i] = sampleDye(cp - step, uSource);
        return;
    }
    vec4 u = dyeValue[uSource + i];  // pass 2: no motion this frame
    if (uPass == 1) {
        vec4 lo, hi;
        sampleDye(cp - step, uSource, lo, hi);
        u = clamp(dyeValue[uForward + i] + 0.5 * (u - sampleDye(cp + step, uForward)), lo, hi);
    }
    u *= uDecay;
    for (int e = 0; e < uEmitters; ++e) {
        float r = emitter[e].posRadius.w;
        // Full strength inside, a one-cell ramp at the rim (no staircase of voxels).
        float a = clamp((r - distance(cp, emitter[e].posRadius.xyz)) / uDyeH + 0.5, 0.0, 1.0);
        u = mix(u, vec4(emitter[e].color.rgb, 1.0), a);
    }
    dyeValue[uTarget + i] = u;
}
