#version 330 core
#include <safegi/prelude.sgl>
// The inverse of the world-to-view matrix takes view to world; a world
// normal goes to view by its transpose, the normal matrix.
space world;
space view;
uniform map<world, view> viewFromWorld;
in normal<world> n;
out normal<view> nView;
void main() {
    mat3 inverseLinear = inverse(mat3(viewFromWorld));
    nView = normalize(transpose(inverseLinear) * n);
    nView = normalize(inverseLinear * n);
    gl_Position = vec4(0.0);
}
