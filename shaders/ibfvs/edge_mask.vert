// IBFVS edge mask [L §IV-E.2]: per mesh edge (lines-adjacency: the edge's two vertices
// and the opposite vertices of its two triangles), drawn only where it is a silhouette.
layout(location = SURFACE_POS_OBJ_LOCATION) in vec3 aPosObj;
uniform mat4 uViewProj;
void main() { gl_Position = uViewProj * vec4(aPosObj, 1.0); }
