// flowsurf — every binding point between C++ and GLSL, in one table: texture units
// (sampler bindings), image units, shader storage bindings, vertex attributes (the surface
// vertex's layout) and fragment outputs. C++ binds with these constants; shader_interface.cpp
// writes each one as a `#define` of its GLSL name, which the shaders' layout qualifiers use,
// so no number is written twice.
//
// Index: binding points, per stage (1) · the list the GLSL is generated from (2) ·
//        vertex attributes and the surface vertex (3) · fragment outputs (4)
//
// Points are numbered per program: two stages may use the same unit for different inputs,
// since each binds its own before it draws; within one program they differ.
#pragma once

#include <cstddef>

namespace flowsurf::methods {

// A texture unit, image unit, storage binding or fragment output location, and the
// `#define` the shaders use for it; its name ends in _UNIT, _IMAGE_UNIT, _BINDING or _OUT.
struct BindingPoint {
    enum Kind { Texture, Image, Storage, Output };
    Kind kind;
    const char* glsl;  // e.g. "OVERLAY_FLOW_UNIT": layout(binding = OVERLAY_FLOW_UNIT)
    int point;
    constexpr operator unsigned() const { return unsigned(point); }
};
constexpr BindingPoint textureUnit(const char* glsl, int unit) { return {BindingPoint::Texture, glsl, unit}; }
constexpr BindingPoint imageUnit(const char* glsl, int unit) { return {BindingPoint::Image, glsl, unit}; }
constexpr BindingPoint storageBinding(const char* glsl, int binding) { return {BindingPoint::Storage, glsl, binding}; }
constexpr BindingPoint fragmentOutput(const char* glsl, int location) { return {BindingPoint::Output, glsl, location}; }

// (1) Binding points, per stage -----------------------------------------------------------
namespace bindings {
// ISA stage 2, advection mesh (isa/advection_mesh.*): the velocity image in, the mesh out.
inline constexpr BindingPoint kMeshVelocity = textureUnit("MESH_VELOCITY_UNIT", 0);         // RGBA32F P-space velocity
inline constexpr BindingPoint kMeshDepth = textureUnit("MESH_DEPTH_UNIT", 1);               // window depth
inline constexpr BindingPoint kMeshSourceDepth = textureUnit("MESH_SOURCE_DEPTH_UNIT", 2);  // the source texture's depth
inline constexpr BindingPoint kMeshImage = imageUnit("MESH_IMAGE_UNIT", 0);                 // RGBA32F (R+1)^2 vertices
// ISA stage 3, texture advection (isa/texture_advection.*).
inline constexpr BindingPoint kIsaPrevFlow = textureUnit("ISA_PREV_FLOW_UNIT", 0);          // F_a(k-1), R32F
inline constexpr BindingPoint kIsaMesh = textureUnit("ISA_MESH_UNIT", 1);                   // the advection mesh
inline constexpr BindingPoint kIsaSurfaceDepth = textureUnit("ISA_SURFACE_DEPTH_UNIT", 2);  // velocity image depth
inline constexpr BindingPoint kIsaNextFlow = imageUnit("ISA_NEXT_FLOW_IMAGE_UNIT", 0);      // F_a(k), R32F
// IBFVS stages 2-3, polygon advection (ibfvs/polygon_advection.*). The previous F_a apart
// from the visibility buffer's units: ibfvs/polygon_resolve.frag reads both.
inline constexpr BindingPoint kIbfvsPrevFlow = textureUnit("IBFVS_PREV_FLOW_UNIT", 2);      // F_a(k-1), R32F
inline constexpr BindingPoint kIbfvsTexcoord = textureUnit("IBFVS_TEXCOORD_UNIT", 0);       // RG32F, from the draw
inline constexpr BindingPoint kIbfvsDepth = textureUnit("IBFVS_DEPTH_UNIT", 1);             // the draw's depth
inline constexpr BindingPoint kIbfvsNextFlow = imageUnit("IBFVS_NEXT_FLOW_IMAGE_UNIT", 0);  // F_a(k), R32F
inline constexpr BindingPoint kIbfvsBounds = storageBinding("IBFVS_BOUNDS_BINDING", 0);     // tiles: what a tile reads
// Noise injection [L eq. 9] (common/noise_injection.*), beside either advection's units.
inline constexpr BindingPoint kNoisePhases = textureUnit("NOISE_PHASES_UNIT", 3);  // R32F phase per noise cell
// IBFVS edge mask (ibfvs/edge_mask.*): the surface depth, and the outline quads shared
// between processes (an SSBO apart from the dye and visibility ones).
inline constexpr BindingPoint kEdgeMaskDepth = textureUnit("EDGE_MASK_DEPTH_UNIT", 0);
inline constexpr BindingPoint kEdgeCapture = storageBinding("EDGE_CAPTURE_BINDING", 9);
// Hybrid particle tracing (hybrid/particle_tracing.*): the seed velocity image, the velocity
// (one image, or one layer per time level when unsteady), the solid noise, I out.
inline constexpr BindingPoint kLicSeedVelocity = textureUnit("LIC_SEED_VELOCITY_UNIT", 0);
inline constexpr BindingPoint kLicVelocity = textureUnit("LIC_VELOCITY_UNIT", 1);  // sampler2D, or sampler3D of levels
inline constexpr BindingPoint kLicNoise = imageUnit("LIC_NOISE_IMAGE_UNIT", 1);    // RGBA8 3D, read as an image
inline constexpr BindingPoint kLicImage = imageUnit("LIC_IMAGE_UNIT", 0);          // I, R32F
// Hybrid solid noise (hybrid/solid_noise.*): the packed RGBA8 texture as 32-bit words.
inline constexpr BindingPoint kSolidNoiseImage = imageUnit("SOLID_NOISE_IMAGE_UNIT", 0);
// Overlay [L eq. 10] (common/overlay.*): its inputs and, on the compute path, the composite.
inline constexpr BindingPoint kOverlayFlow = textureUnit("OVERLAY_FLOW_UNIT", 0);          // F_a or I, channel r
inline constexpr BindingPoint kOverlayDepth = textureUnit("OVERLAY_DEPTH_UNIT", 1);        // 1 = background
inline constexpr BindingPoint kOverlayShade = textureUnit("OVERLAY_SHADE_UNIT", 2);        // eye normal, colour value
inline constexpr BindingPoint kOverlayColormap = textureUnit("OVERLAY_COLORMAP_UNIT", 3);  // 256 x 1 RGBA8
inline constexpr BindingPoint kOverlayMask = textureUnit("OVERLAY_MASK_UNIT", 4);          // texture mask value
inline constexpr BindingPoint kOverlayLegend = textureUnit("OVERLAY_LEGEND_UNIT", 5);      // RGBA8, alpha = coverage
inline constexpr BindingPoint kOverlayImage = imageUnit("OVERLAY_IMAGE_UNIT", 0);          // the composite, RGBA8
// Dye (common/dye.*): the band's index texture and storage, read by the overlay as well.
inline constexpr BindingPoint kDyeIndex = textureUnit("DYE_INDEX_UNIT", 6);                // isampler3D: band voxel per cell
inline constexpr BindingPoint kDyeValue = storageBinding("DYE_VALUE_BINDING", 0);          // three slots of values per voxel
inline constexpr BindingPoint kDyeBand = storageBinding("DYE_BAND_BINDING", 1);            // closest point, velocity per voxel
inline constexpr BindingPoint kDyeSource = storageBinding("DYE_SOURCE_BINDING", 2);        // this frame's emitters
inline constexpr BindingPoint kDyeDeparture = storageBinding("DYE_DEPARTURE_BINDING", 3);  // departure point per voxel
inline constexpr BindingPoint kDyeFlag = storageBinding("DYE_FLAG_BINDING", 4);            // per brick: 1 where dye was left
inline constexpr BindingPoint kDyeActive = storageBinding("DYE_ACTIVE_BINDING", 5);        // the voxels a step updates
// Visibility buffer (common/visibility_buffer.*).
inline constexpr BindingPoint kVisVertex = textureUnit("VIS_VERTEX_UNIT", 0);                 // samplerBuffer: the vertices
inline constexpr BindingPoint kVisTriangle = textureUnit("VIS_TRIANGLE_UNIT", 1);             // usamplerBuffer: the triangles
inline constexpr BindingPoint kVisDepth = storageBinding("VIS_DEPTH_BINDING", 2);             // per pixel: least depth (bits)
inline constexpr BindingPoint kVisId = storageBinding("VIS_ID_BINDING", 3);                   // per pixel: least triangle id there
inline constexpr BindingPoint kVisIndirect = storageBinding("VIS_INDIRECT_BINDING", 4);       // the GL part's draw, deferred count
inline constexpr BindingPoint kVisDeferred = storageBinding("VIS_DEFERRED_BINDING", 5);       // deferred triangles' indices
inline constexpr BindingPoint kVisDeferredId = storageBinding("VIS_DEFERRED_ID_BINDING", 6);  // deferred triangles' ids
inline constexpr BindingPoint kVisCovering = storageBinding("VIS_COVERING_BINDING", 7);       // triangles on a pixel centre
// The occlusion step's cells (VisibilityBuffer::dropOccluded; it binds no indirect block).
inline constexpr BindingPoint kVisOccluder = storageBinding("VIS_OCCLUDER_BINDING", 4);       // per cell: farthest depth (bits)
// Contrast enhancement [doc/contrast.md] (common/contrast_*, percentile_range.*): the histogram
// (an SSBO apart from the dye and visibility ones) and the stretch pass.
inline constexpr BindingPoint kHistogram = storageBinding("HISTOGRAM_BINDING", 8);
inline constexpr BindingPoint kContrastFlow = textureUnit("CONTRAST_FLOW_UNIT", 0);    // F_a or I, channel r
inline constexpr BindingPoint kContrastDepth = textureUnit("CONTRAST_DEPTH_UNIT", 1);  // window depth
inline constexpr BindingPoint kContrastImage = imageUnit("CONTRAST_IMAGE_UNIT", 0);    // the stretched texture, R32F
// The flow topology layer (skeleton_layer/*): the surface depth that hides it, its line
// pieces and its critical points.
inline constexpr BindingPoint kSkeletonDepth = textureUnit("SKELETON_DEPTH_UNIT", 0);              // 1 = background
inline constexpr BindingPoint kSkeletonSegments = storageBinding("SKELETON_SEGMENTS_BINDING", 0);  // 2 vec4 a piece
inline constexpr BindingPoint kSkeletonPoints = storageBinding("SKELETON_POINTS_BINDING", 1);      // 1 vec4 a point
// ParaView's composite of a method's image into its view (paraview/composite.frag).
inline constexpr BindingPoint kCompositeColor = textureUnit("COMPOSITE_COLOR_UNIT", 0);  // the method's composite, RGBA8
inline constexpr BindingPoint kCompositeDepth = textureUnit("COMPOSITE_DEPTH_UNIT", 1);  // its surface depth
inline constexpr BindingPoint kCompositeShade = textureUnit("COMPOSITE_SHADE_UNIT", 2);  // eye normal, colour value
inline constexpr BindingPoint kCompositeTable = textureUnit("COMPOSITE_TABLE_UNIT", 3);  // ParaView's 256 x 1 table
}  // namespace bindings

// (2) Every point above, for the generated GLSL (a point missing here fails its shader's
// compile with the name undeclared).
inline constexpr BindingPoint kBindingPoints[] = {
    bindings::kMeshVelocity, bindings::kMeshDepth, bindings::kMeshSourceDepth, bindings::kMeshImage,
    bindings::kIsaPrevFlow, bindings::kIsaMesh, bindings::kIsaSurfaceDepth, bindings::kIsaNextFlow,
    bindings::kIbfvsPrevFlow, bindings::kIbfvsTexcoord, bindings::kIbfvsDepth, bindings::kIbfvsNextFlow,
    bindings::kIbfvsBounds,
    bindings::kNoisePhases, bindings::kEdgeMaskDepth, bindings::kEdgeCapture,
    bindings::kLicSeedVelocity, bindings::kLicVelocity, bindings::kLicNoise, bindings::kLicImage,
    bindings::kSolidNoiseImage,
    bindings::kOverlayFlow, bindings::kOverlayDepth, bindings::kOverlayShade, bindings::kOverlayColormap,
    bindings::kOverlayMask, bindings::kOverlayLegend, bindings::kOverlayImage,
    bindings::kDyeIndex, bindings::kDyeValue, bindings::kDyeBand, bindings::kDyeSource, bindings::kDyeDeparture,
    bindings::kDyeFlag, bindings::kDyeActive,
    bindings::kVisVertex, bindings::kVisTriangle, bindings::kVisDepth, bindings::kVisId, bindings::kVisIndirect,
    bindings::kVisDeferred, bindings::kVisDeferredId, bindings::kVisCovering, bindings::kVisOccluder,
    bindings::kHistogram, bindings::kContrastFlow, bindings::kContrastDepth, bindings::kContrastImage,
    bindings::kSkeletonDepth, bindings::kSkeletonSegments, bindings::kSkeletonPoints,
    bindings::kCompositeColor, bindings::kCompositeDepth, bindings::kCompositeShade, bindings::kCompositeTable,
};

// The highest point of `kind` in the table (-1: none): what a caller that saves and restores
// the host's bindings must cover (the ParaView plugin's GlStateGuard).
constexpr int highestPoint(BindingPoint::Kind kind) {
    int highest = -1;
    for (const BindingPoint& b : kBindingPoints)
        if (b.kind == kind && b.point > highest) highest = b.point;
    return highest;
}

// (3) Vertex attributes -------------------------------------------------------------------
// One attribute: its location, its float count, its offset in floats from the start of its
// vertex, and the vertex array's buffer binding it reads from (C++ only). The GLSL gets
// <glsl>_LOCATION and <glsl>_OFFSET.
struct VertexAttribute {
    const char* glsl;
    int location;
    int components;
    int offset;
    unsigned buffer;
    constexpr int end() const { return offset + components; }
    // The same attribute from a buffer that holds it alone (offset 0).
    constexpr VertexAttribute alone() const { return {glsl, location, components, 0, buffer}; }
};

namespace surface_vertex {
// SurfaceGpu's interleaved vertex: position, normal, P-space advection velocity, colour
// value and mask value (both mapped to 0..1 by their ranges, NaN where undefined).
inline constexpr unsigned kBuffer = 0;
inline constexpr VertexAttribute kPosObj{"SURFACE_POS_OBJ", 0, 3, 0, kBuffer};
inline constexpr VertexAttribute kNormalObj{"SURFACE_NORMAL_OBJ", 1, 3, kPosObj.end(), kBuffer};
inline constexpr VertexAttribute kVelObj{"SURFACE_VEL_OBJ", 2, 3, kNormalObj.end(), kBuffer};
inline constexpr VertexAttribute kColor{"SURFACE_COLOR", 3, 1, kVelObj.end(), kBuffer};
inline constexpr VertexAttribute kMask{"SURFACE_MASK", 4, 1, kColor.end(), kBuffer};
inline constexpr VertexAttribute kAttributes[] = {kPosObj, kNormalObj, kVelObj, kColor, kMask};
// Padded to whole RGBA32F texels (VERTEX_TEXELS in GLSL), so that the vertex buffer is also
// a buffer texture: the visibility pass fetches vertices from it.
inline constexpr int kTexels = (kMask.end() + 3) / 4;
inline constexpr int kFloats = kTexels * 4;
inline constexpr int kStride = kFloats * int(sizeof(float));
static_assert(kPosObj.offset % 4 == 0, "vertexPosition (visibility.glsl) fetches the position as one texel");
}  // namespace surface_vertex

// A time level's two raw fields (hybrid/velocity_levels.*), each a buffer of vec3 of its
// own, beside the surface vertex's position and normal.
inline constexpr VertexAttribute kLevelFieldA{"LEVEL_FIELD_A", 5, 3, 0, 1};
inline constexpr VertexAttribute kLevelFieldB{"LEVEL_FIELD_B", 6, 3, 0, 2};

// Every attribute above, for the generated GLSL.
inline constexpr VertexAttribute kVertexAttributes[] = {surface_vertex::kPosObj, surface_vertex::kNormalObj,
                                                        surface_vertex::kVelObj,  surface_vertex::kColor,
                                                        surface_vertex::kMask,    kLevelFieldA,
                                                        kLevelFieldB};

// (4) Fragment outputs --------------------------------------------------------------------
// A colour output's location is the index of the colour attachment it is drawn into
// (gl::Framebuffer::finish draws buffer i to attachment i).
namespace outputs {
// The surface G-buffer (raster/surface_gbuffer.frag, raster/visibility_resolve.frag).
inline constexpr BindingPoint kVelObj = fragmentOutput("VEL_OBJ_OUT", 0);  // xyz: P-space velocity, w: layer depth
inline constexpr BindingPoint kShade = fragmentOutput("SHADE_OUT", 1);     // xyz: eye-space normal, w: colour value
inline constexpr BindingPoint kMask = fragmentOutput("MASK_OUT", 2);       // texture mask value
inline constexpr BindingPoint kPosObj = fragmentOutput("POS_OBJ_OUT", 3);  // P-space position (hybrid)
// F_a into a FlowPingPong (isa/texture_advection.frag; ibfvs/polygon_advection.frag, which
// also writes the shade and mask above, or the texture coordinate on the compute path).
inline constexpr BindingPoint kFlow = fragmentOutput("FLOW_OUT", 0);
// A time level's velocity into a layer of the levels' 3D texture (hybrid/velocity_levels.frag).
inline constexpr BindingPoint kLevelVelocity = fragmentOutput("LEVEL_VELOCITY_OUT", 0);
}  // namespace outputs

// Every output above, for the generated GLSL.
inline constexpr BindingPoint kFragmentOutputs[] = {outputs::kVelObj, outputs::kShade, outputs::kMask,
                                                    outputs::kPosObj, outputs::kFlow,  outputs::kLevelVelocity};

}  // namespace flowsurf::methods
