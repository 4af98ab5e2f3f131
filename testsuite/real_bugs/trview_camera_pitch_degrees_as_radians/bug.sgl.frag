#version 330 core
#include <safegi/prelude.sgl>
// A level viewer's free camera, drawing the environment behind the level:
// with the viewer's 'degrees' setting on, the yaw and the pitch typed into the
// camera panel are degrees, and both are converted to radians before the
// camera's forward axis (and from it each pixel's eye ray) is built.
space world;

uniform float<angle in degree> yawDeg;
uniform float<angle in degree> pitchDeg;
uniform direction<world> worldUp;
uniform float tanHalfFov;
uniform float aspect;
uniform samplerCube<spectrum<radiance>, world> environment;

in vec2 ndc;                      // -1 .. 1
out vec4 fragColor;

void main() {
    float yaw = radians(yawDeg);
    float pitch = pitchDeg;
    direction<world> forward = direction<world>(vec3(cos(pitch) * sin(yaw), sin(pitch), cos(pitch) * cos(yaw)));
    vec3 right = normalize(cross(forward, worldUp));
    vec3 up = cross(right, forward);
    vec3 ray = normalize(forward + right * (ndc.x * tanHalfFov * aspect) + up * (ndc.y * tanHalfFov));
    fragColor = vec4(texture(environment, ray).rgb, 1.0);
}
