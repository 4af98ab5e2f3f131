#version 330 core
#include <safegi/prelude.sgl>
// The screen-space derivative of a position is a displacement of its space
// (a face normal from cross(dFdx(P), dFdy(P))), of a vector, direction or normal
// a vector of its space: derivatives of two spaces do not meet.
space world;
space view;
in point<world> P;
in point<view> Pv;
out vec4 c;
void main() {
    vector<world> dx = dFdx(P);
    vec3 n = normalize(cross(dx, dFdy(P)));
    vec3 wrong = cross(dFdx(P), dFdy(Pv));
    c = vec4(n, 1.0);
}
