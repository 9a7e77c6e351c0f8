// IBFVS under parallel = tiles (ibfvs_renderer.cpp): the box, in texels of the previous
// F_a, of the texture coordinates the surface's pixels of a rectangle read it at, so that
// a tile pulls only that part of the history (ScreenTiles::pull). A box per work group in
// shared memory, then one atomic per side and group into the buffer.
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = IBFVS_TEXCOORD_UNIT) uniform sampler2D uTexcoord;  // RG32F, the merged draw's
layout(binding = IBFVS_DEPTH_UNIT) uniform sampler2D uDepth;        // the merged depth, 1 = background
layout(std430, binding = IBFVS_BOUNDS_BINDING) buffer Bounds {
    int box[4];  // x0, y0, x1, y1 (texels, inclusive); x0 > x1 when no pixel is on the surface
};
uniform ivec2 uOrigin;  // the pixels read: [uOrigin, uEnd)
uniform ivec2 uEnd;
shared int groupBox[4];
void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupBox[0] = 0x7fffffff;
        groupBox[1] = 0x7fffffff;
        groupBox[2] = -0x7fffffff;
        groupBox[3] = -0x7fffffff;
    }
    barrier();
    ivec2 p = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, uEnd)) && texelFetch(uDepth, p, 0).r < 1.0) {
        // Beyond the texture a coordinate reads its edge (clamp to edge).
        vec2 size = vec2(textureSize(uTexcoord, 0));
        vec2 t = clamp(texelFetch(uTexcoord, p, 0).xy * size, vec2(-1.0), size + 1.0);
        atomicMin(groupBox[0], int(floor(t.x)));
        atomicMin(groupBox[1], int(floor(t.y)));
        atomicMax(groupBox[2], int(ceil(t.x)));
        atomicMax(groupBox[3], int(ceil(t.y)));
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupBox[0] <= groupBox[2]) {
        atomicMin(box[0], groupBox[0]);
        atomicMin(box[1], groupBox[1]);
        atomicMax(box[2], groupBox[2]);
        atomicMax(box[3], groupBox[3]);
    }
}
