// Hybrid, unsteady flow: the velocity of one time level on the frame's surface [W §3].
// The level's field is a blend of two steps' raw vectors; it is made tangential to the
// frame's normals and scaled as the steady path scales the frame's field (§0, [W §3]:
// normalised, or clamped at the frame's speed percentile), then divided by the frame's
// reference speed so that 16-bit targets keep precision whatever the data's units.
layout(location = SURFACE_POS_OBJ_LOCATION) in vec3 aPosObj;
layout(location = SURFACE_NORMAL_OBJ_LOCATION) in vec3 aNormalObj;
layout(location = LEVEL_FIELD_A_LOCATION) in vec3 aFieldA;
layout(location = LEVEL_FIELD_B_LOCATION) in vec3 aFieldB;
uniform mat4 uViewProj;
uniform vec4 uLayerDepthRow;  // methods::layerDepthRow
uniform float uWeight;
uniform int uNormalize;
uniform float uClampSpeed;  // 0: none
uniform float uInvSpeedRef;
out vec3 vVel;
out float vLayerDepth;
void main() {
    vec3 v = mix(aFieldA, aFieldB, uWeight);
    v -= dot(v, aNormalObj) * aNormalObj;
    float s = length(v);
    if (uNormalize != 0 && s > 0.0) v /= s;
    else if (uClampSpeed > 0.0 && s > uClampSpeed) v *= uClampSpeed / s;
    vVel = v * uInvSpeedRef;
    vLayerDepth = dot(uLayerDepthRow, vec4(aPosObj, 1.0));
    gl_Position = uViewProj * vec4(aPosObj, 1.0);
}
