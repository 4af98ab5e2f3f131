#version 300 es
#include <safegi/prelude.sgl>
// A glTF viewer's PBR vertex shader: glTF nodes may scale non-uniformly, so
// the normal goes through the normal matrix the application uploads (the
// inverse transpose of the model matrix), the position through the model
// matrix.
space object;
space world;
space clip;

uniform map<object, world> u_ModelMatrix;
uniform mat4 u_NormalMatrix;                          // transpose(inverse(u_ModelMatrix))
uniform projmap<object, clip> u_MVPMatrix;

in point<object> a_Position;
in normal<object> a_Normal;
out point<world> v_Position;
out normal<world> v_Normal;

void main() {
    vec4 pos = u_ModelMatrix * vec4(a_Position, 1.0);
    v_Position = vec3(pos.xyz) / pos.w;
    v_Normal = normalize(vec3(u_NormalMatrix * vec4(a_Normal, 0.0)));
    gl_Position = u_MVPMatrix * vec4(a_Position, 1.0);
}
