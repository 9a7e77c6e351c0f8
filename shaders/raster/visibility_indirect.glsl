// The visibility pass's counters and indirect commands (raster/visibility_buffer.cpp,
// kIndirectWords): the GL part's DrawElementsIndirectCommand, the number of triangles
// deferred to it, the number of triangles the first pass found covering a pixel, and the
// second pass's DispatchIndirectCommand over those.
layout(std430, binding = VIS_INDIRECT_BINDING) coherent buffer Indirect {
    uint drawCount, instanceCount, firstIndex, baseVertex, baseInstance;
    uint deferredCount;
    uint coveringCount;
    uint dispatchX, dispatchY, dispatchZ;
};
