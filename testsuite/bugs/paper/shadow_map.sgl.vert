#version 330 core
#include <safegi/prelude.sgl>
// The paper's shadow-map pass: positions to the light's clip space; the depth
// written is a length along the light's axis (sampler2D<float<length>>).
space object_s;
space world_s;
space light_s;
space clip_s;

uniform map<object_s, world_s> worldFromObject;
uniform rigidmap<world_s, light_s> lightFromWorld;
uniform projmap<light_s, clip_s> clipFromLight;

in point<object_s> position;
out float<length> lightDepth;

void main() {
    point<light_s> pl = lightFromWorld * (worldFromObject * position);
    hpoint<clip_s> h = clipFromLight * pl;
    lightDepth = -pl.z;
    gl_Position = h;
}
