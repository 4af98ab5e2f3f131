#version 330 core
#include <safegi/prelude.sgl>
// A glTF viewer's vertex shader: world position, normal and tangent frame for
// normal mapping. A normal is a direction: its homogeneous w is 0, so the
// model matrix's translation does not move it.
space object;
space world;
space clip;

uniform map<object, world> u_ModelMatrix;
uniform projmap<object, clip> u_MVPMatrix;

in point<object> a_Position;
in normal<object> a_Normal;
in vector<object> a_Tangent;
out point<world> v_Position;
out normal<world> v_Normal;
out vector<world> v_Tangent;

void main() {
    vec4 pos = u_ModelMatrix * vec4(a_Position, 1.0);
    v_Position = vec3(pos.xyz) / pos.w;
    v_Normal = normalize(vec3(u_ModelMatrix * vec4(a_Normal, 1.0)));
    v_Tangent = vec3(u_ModelMatrix * vec4(a_Tangent, 0.0));
    gl_Position = u_MVPMatrix * vec4(a_Position, 1.0);
}
