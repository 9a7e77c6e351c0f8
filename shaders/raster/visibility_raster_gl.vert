// Visibility pass, GL part: the triangles the compute part deferred (large, or crossing the
// eye plane), clipped and rasterised by GL, into the same visibility buffer.
layout(location = SURFACE_POS_OBJ_LOCATION) in vec3 aPosObj;
uniform mat4 uViewProj;
void main() { gl_Position = uViewProj * vec4(aPosObj, 1.0); }
