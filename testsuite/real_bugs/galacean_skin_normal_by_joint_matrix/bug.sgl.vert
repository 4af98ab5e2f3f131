#version 300 es
#include <safegi/prelude.sgl>
// Web engine's skinning: the weighted joint matrices move the bind-pose
// position into the mesh's object space; the normal is carried by the inverse
// transpose of the blend's linear part, written as the normal (a row vector)
// times its inverse, so joints that scale keep normals perpendicular.
precision highp float;
space bind;
space object;
space world;
space clip;

uniform mat4 u_jointMatrix[32];                  // bind pose -> object, one per joint
uniform mat3<object, world, normal> u_normalMat;
uniform projmap<object, clip> u_MVPMat;

in point<bind> POSITION;
in normal<bind> NORMAL;
in vec4 JOINTS_0;
in vec4 WEIGHTS_0;
out normal<world> v_normal;

void main() {
    map<bind, object> skinMatrix =
        WEIGHTS_0.x * u_jointMatrix[int(JOINTS_0.x)] +
        WEIGHTS_0.y * u_jointMatrix[int(JOINTS_0.y)] +
        WEIGHTS_0.z * u_jointMatrix[int(JOINTS_0.z)] +
        WEIGHTS_0.w * u_jointMatrix[int(JOINTS_0.w)];
    vec4 position = skinMatrix * vec4(POSITION, 1.0);
    vec3 n = vec4(skinMatrix * vec4(NORMAL, 0.0)).xyz;
    gl_Position = u_MVPMat * position;
    v_normal = normalize(u_normalMat * n);
}
