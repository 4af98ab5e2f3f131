#version 450
#include <safegi/prelude.sgl>
// A social-VR engine's textured particles, billboarded in eye space: each
// quad faces the eye it is rendered for, its right axis perpendicular to the
// ray from that eye to the particle and to the up direction (in VR each eye
// has its own view, and the quad must turn toward it, not along the view axis).
space world;
space eye : eye;
space clip;

uniform rigidmap<world, eye> viewFromWorld;       // this eye's view
uniform projmap<eye, clip> clipFromEye;
uniform direction<world> upWorld;

layout(location = 0) in point<world> particleCenter;
layout(location = 1) in vec2 quadCorner;          // -0.5 .. 0.5
layout(location = 2) in float<length> particleSize;

void main() {
    vec4 anchorPoint = viewFromWorld * vec4(particleCenter, 1.0);
    vec3 upEye = normalize(mat3(viewFromWorld) * upWorld);
    vec3 eyeToParticle = normalize(anchorPoint.xyz);
    vec3 particleRight = normalize(cross(eyeToParticle, upEye));
    vec3 particleUp = cross(particleRight, eyeToParticle);
    point<eye> corner = anchorPoint.xyz + (quadCorner.x * particleSize) * particleRight
                                        + (quadCorner.y * particleSize) * particleUp;
    gl_Position = clipFromEye * vec4(corner, 1.0);
}
