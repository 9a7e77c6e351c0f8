// IBFVS under parallel = tiles (ibfvs_renderer.cpp): the box, in texels of the previous
// F_a, of the texture coordinates the surface's pixels of a rectangle read it at, so that
// a tile pulls only that part of the history (ScreenTiles::pull). Each invocation walks one
// column of BOUNDS_ROWS pixels (the work group's invocations side by side, so that a SIMD
// batch reads neighbouring pixels), keeps its box in registers, and adds it with one atomic
// per side. No shared memory and no barrier: llvmpipe runs a barrier by switching between
// the group's invocations one at a time, which cost more than the reads themselves.
layout(local_size_x = BOUNDS_COLUMNS) in;
layout(binding = IBFVS_TEXCOORD_UNIT) uniform sampler2D uTexcoord;  // RG32F, the merged draw's
layout(binding = IBFVS_DEPTH_UNIT) uniform sampler2D uDepth;        // the merged depth, 1 = background
layout(std430, binding = IBFVS_BOUNDS_BINDING) buffer Bounds {
    int box[4];  // x0, y0, x1, y1 (texels, inclusive); x0 > x1 when no pixel is on the surface
};
uniform ivec2 uOrigin;  // the pixels read: [uOrigin, uEnd)
uniform ivec2 uEnd;
void main() {
    int x = uOrigin.x + int(gl_GlobalInvocationID.x);
    int y0 = uOrigin.y + int(gl_GlobalInvocationID.y) * BOUNDS_ROWS;
    int y1 = min(y0 + BOUNDS_ROWS, uEnd.y);
    if (x >= uEnd.x) return;
    // Beyond the texture a coordinate reads its edge (clamp to edge).
    vec2 size = vec2(textureSize(uTexcoord, 0));
    ivec2 lo = ivec2(0x7fffffff), hi = ivec2(-0x7fffffff);
    for (int y = y0; y < y1; ++y) {
        ivec2 p = ivec2(x, y);
        if (texelFetch(uDepth, p, 0).r < 1.0) {
            vec2 t = clamp(texelFetch(uTexcoord, p, 0).xy * size, vec2(-1.0), size + 1.0);
            lo = min(lo, ivec2(floor(t)));
            hi = max(hi, ivec2(ceil(t)));
        }
    }
    if (lo.x <= hi.x) {
        atomicMin(box[0], lo.x);
        atomicMin(box[1], lo.y);
        atomicMax(box[2], hi.x);
        atomicMax(box[3], hi.y);
    }
}
