#version 330 core
// Geometry seen from a light, one cube face at a time: world space for the
// distance the fragment stage stores, the face's clip space for the rasteriser.
#include <safegi/prelude.sgl>

space object;
space world;
space light_clip;

uniform map<object, world>         worldFromObject;
uniform projmap<world, light_clip> lightClipFromWorld;

layout(location = 0) in point<object> position;

out point<world> P;

void main() {
    P = worldFromObject * position;
    gl_Position = lightClipFromWorld * P;
}
