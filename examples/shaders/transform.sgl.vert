#version 330 core
// Object-space geometry to world space for shading and to clip space for the
// rasteriser. Normals use the inverse transpose (a non-rigid map).
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
