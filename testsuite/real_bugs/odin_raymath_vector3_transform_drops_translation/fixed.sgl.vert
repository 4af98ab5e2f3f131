#version 330 core
#include <safegi/prelude.sgl>
// A language's bindings of a games library's math module: Vector3Transform
// applies a 4x4 transform to a position, so the position is extended with
// w = 1 and the matrix's translation is applied (the C library adds the
// translation terms written out). Here a billboard's anchor goes through it.
space object_s;
space world;
space clip;

uniform map<object_s, world> transform;
uniform projmap<world, clip> viewProj;

in point<object_s> anchor;

point<world> Vector3Transform(point<object_s> v, map<object_s, world> mat) {
    vec4 result = mat * vec4(v, 1.0);
    return result.xyz;
}

void main() {
    point<world> p = Vector3Transform(anchor, transform);
    gl_Position = viewProj * vec4(p, 1.0);
}
