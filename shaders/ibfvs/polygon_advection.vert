// IBFVS stage 2, polygonal texture advection [L §IV-D.2]: the surface at T(x_i) with
// texture coordinates from the mesh projection, interpolated linearly in screen space
// (noperspective) so large triangles at a steep depth gradient show no artefact
// [L §IV-J].
#include "ibfvs/mesh_projection.glsl"
layout(location = SURFACE_POS_OBJ_LOCATION) in vec3 aPosObj;
layout(location = SURFACE_NORMAL_OBJ_LOCATION) in vec3 aNormalObj;
layout(location = SURFACE_VEL_OBJ_LOCATION) in vec3 aVelObj;
layout(location = SURFACE_COLOR_LOCATION) in float aColor;
layout(location = SURFACE_MASK_LOCATION) in float aMask;
uniform mat4 uViewProj;
uniform mat4 uPrevViewProj;
uniform mat4 uView;
uniform float uDt;
noperspective out vec2 vTexcoord;
out vec3 vNormalEye;
out float vColor;
out float vMask;
void main() {
    vTexcoord = pathlineTexcoord(aPosObj, aVelObj, uDt, uPrevViewProj);
    vNormalEye = mat3(uView) * aNormalObj;
    vColor = aColor;
    vMask = aMask;
    gl_Position = uViewProj * vec4(aPosObj, 1.0);
}
