#version 330 core
#include <safegi/prelude.sgl>
// A skybox pass: the ray through the fragment arrives in view space, goes to
// world space through the camera's rotation, and only then through the
// skybox's own rotation, so that rotating the skybox turns the sky about the
// world's axes and not the camera's. Both steps carry a direction: w = 0.
space view;
space world;
space sky;

uniform rigidmap<view, world> worldFromView;
uniform rigidmap<world, sky> skyFromWorld;           // the skybox's rotation
uniform samplerCube<spectrum<radiance>, sky> skybox;
uniform float<1> brightness;

in vector<view> vViewRay;
out vec4 fragColor;

void main() {
    vec3 worldRay = (worldFromView * vec4(vViewRay, 0.0)).xyz;
    vec3 skyRay = (skyFromWorld * vec4(worldRay, 0.0)).xyz;
    spectrum<radiance> color = texture(skybox, normalize(skyRay)).rgb * brightness;
    fragColor = vec4(color, 1.0);
}
