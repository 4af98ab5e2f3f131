#version 330 core
#include <safegi/prelude.sgl>
// Values converted with 'in': the checker finds the chain of maps and emits it.
// Motion blur keeps two object-to-world maps, so that step stays explicit.
space object;
space world;
space view;
space clip;
space light;

uniform map<object, world> worldFromObject;
uniform map<object, world> prevWorldFromObject;        // last frame's
uniform rigidmap<world, view> viewFromWorld;
uniform projmap<view, clip> clipFromView;
uniform rigidmap<world, light> lightFromWorld;
uniform point<light> lightOrigin;

in point<object> position;
in normal<object> normalIn;
out point<view> viewPos;
out normal<view> viewNormal;
out point<view> lightPosView;
out vector<world> motion;

void main() {
    point<world> P = worldFromObject * position;
    normal<world> n = worldFromObject * normalIn;
    viewPos = P in view;
    viewNormal = normalize(n in view);
    lightPosView = lightOrigin in view;
    motion = P - prevWorldFromObject * position;
    gl_Position = P in clip;
}
