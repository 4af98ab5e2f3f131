#version 330 core
#include <safegi/prelude.sgl>
// A point carried by affine maps as vec4(p, 1.0) keeps w = 1: dividing its
// xyz by that w (code written for any projection) is the point itself.
space world;
space view;
space clip;
uniform map<world, view> viewFromWorld;
uniform projmap<view, clip> clipFromView;
uniform point<world> lightPos;
in point<world> P;
out vector<view> toLight;
void main() {
    vec4 light = viewFromWorld * vec4(lightPos, 1.0);
    vec4 here = viewFromWorld * vec4(P, 1.0);
    toLight = light.xyz / light.w - here.xyz;
    vec4 projected = clipFromView * here;
    gl_Position = projected;
}
