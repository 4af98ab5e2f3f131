#version 330 core
// Object-space geometry to world space for shading and to the camera's clip
// space for the rasteriser. Shared by every pass that sees the scene through
// the camera, so that their depths agree exactly.
#include <safegi/prelude.sgl>

space object;
space world;
space clip;

uniform map<object, world>   worldFromObject;
uniform projmap<world, clip> clipFromWorld;

layout(location = 0) in point<object>  position;
layout(location = 1) in normal<object> objectNormal;

out point<world>  P;
out normal<world> N;

void main() {
    P = worldFromObject * position;
    N = normalize(worldFromObject * objectNormal);
    gl_Position = clipFromWorld * P;
}
