#version 330 core
#include <safegi/prelude.sgl>
// Vertex stage of a glTF PBR viewer: positions by the model matrix, normals
// by the normal matrix (the inverse transpose of the model matrix, computed
// on the host).
space object;
space world;
space clip;

uniform map<object, world> u_ModelMatrix;
uniform mat4 u_NormalMatrix;
uniform projmap<object, clip> u_MVPMatrix;

in point<object> a_Position;
in normal<object> a_Normal;
out point<world> v_Position;
out normal<world> v_Normal;

void main() {
    vec4 pos = u_ModelMatrix * vec4(a_Position, 1.0);
    v_Position = vec3(pos.xyz) / pos.w;
    v_Normal = normalize(vec3(u_ModelMatrix * vec4(a_Normal.xyz, 0.0)));
    gl_Position = u_MVPMatrix * vec4(a_Position, 1.0);
}
