// Dye [doc/algorithms.md §10], shared by the band passes and the overlay: trilinear interpolation of
// the band values at an object-space point, weights renormalised over the corners that
// lie in the band (a corner outside holds no dye, not zero dye).
layout(binding = DYE_INDEX_UNIT) uniform isampler3D uDyeIndex;  // band voxel per grid cell, -1: none
layout(std430, binding = DYE_VALUE_BINDING) buffer DyeValues { vec4 dyeValue[]; };
uniform vec3 uDyeOrigin;  // corner of grid cell (0,0,0), object space
uniform float uDyeH;      // cell size, object units

// Band value of grid cell c in the slot starting at `slot`, with w the corner's weight.
void dyeCorner(ivec3 c, float w, int slot, inout vec4 sum, inout float wsum, inout vec4 lo, inout vec4 hi) {
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, textureSize(uDyeIndex, 0)))) return;
    int i = texelFetch(uDyeIndex, c, 0).r;
    if (i < 0) return;
    vec4 v = dyeValue[slot + i];
    sum += w * v;
    wsum += w;
    lo = min(lo, v);
    hi = max(hi, v);
}

// The dye at posObj; lo/hi: the extremes of the corners used (the MacCormack limiter).
vec4 sampleDye(vec3 posObj, int slot, out vec4 lo, out vec4 hi) {
    vec3 g = (posObj - uDyeOrigin) / uDyeH - 0.5;
    ivec3 base = ivec3(floor(g));
    vec3 f = g - vec3(base);
    vec4 sum = vec4(0.0);
    float wsum = 0.0;
    lo = vec4(1e30);
    hi = vec4(-1e30);
    for (int k = 0; k < 8; ++k) {
        ivec3 o = ivec3(k & 1, (k >> 1) & 1, k >> 2);
        vec3 w3 = mix(1.0 - f, f, vec3(o));
        dyeCorner(base + o, w3.x * w3.y * w3.z, slot, sum, wsum, lo, hi);
    }
    if (wsum <= 0.0) {
        lo = hi = vec4(0.0);
        return vec4(0.0);
    }
    return sum / wsum;
}

vec4 sampleDye(vec3 posObj, int slot) {
    vec4 lo, hi;
    return sampleDye(posObj, slot, lo, hi);
}
