#version 330 core
#include <safegi/prelude.sgl>
// A game's community shader mod derives the vertical field of view from the
// game's camera field of view (horizontal, in degrees): the half-width of the
// frustum at unit distance is tan(hFOV / 2), the half-height that divided by
// the aspect ratio, and the vertical FOV twice its arctangent. A screen-space
// effect then builds the view ray of each pixel from it.
uniform float<angle in degree> cameraFOVDeg;
uniform float<1> aspect;                          // width / height
uniform vec2 resolution;

out vec4 fragColor;

void main() {
    float hFOVRad = cameraFOVDeg * (3.14159265359 / 180.0);
    float unitHalfWidth = tan(hFOVRad / 2.0);
    float unitHalfHeight = unitHalfWidth / aspect;
    float vFOV = 2.0 * atan(unitHalfHeight);
    vec2 ndc = (gl_FragCoord.xy / resolution) * 2.0 - 1.0;
    float tanHalfV = tan(vFOV * 0.5);
    vec3 ray = normalize(vec3(ndc.x * tanHalfV * aspect, ndc.y * tanHalfV, -1.0));
    fragColor = vec4(ray * 0.5 + 0.5, 1.0);
}
