// Hybrid step 1, seed textures [W §4]: one render of the surface gives every visible pixel
// its P-space position and tangential P-space velocity.
layout(location = 0) in vec3 aPosObj;
layout(location = 1) in vec3 aNormalObj;
layout(location = 2) in vec3 aVelObj;
layout(location = 3) in float aSpeed;
uniform mat4 uViewProj;
uniform mat4 uView;
out vec3 vPosObj;
out vec3 vVelObj;
out vec3 vNormalEye;
out float vSpeed;
void main() {
    vPosObj = aPosObj;
    vVelObj = aVelObj;
    vNormalEye = mat3(uView) * aNormalObj;
    vSpeed = aSpeed;
    gl_Position = uViewProj * vec4(aPosObj, 1.0);
}
