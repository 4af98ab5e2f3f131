#version 450
#include <safegi/prelude.sgl>
// A spot light's bounding box for light culling, built in the light's own
// frame (the light shines down -z): the light reaches no farther than its
// range, so its cone is capped by that sphere and the box's half width is
// range * sin(angle); the tangent would grow without bound toward 90 degrees.
space light_s;
space view;
space clip;

uniform rigidmap<light_s, view> viewFromLight;
uniform projmap<view, clip> clipFromView;
uniform float<length> range;
uniform float<angle> spotAngle;                 // half angle, below 90 degrees

in vec3 corner;                                 // a unit box corner, each coordinate 0 or 1

void main() {
    float<length> size = sin(spotAngle) * range;
    vec3 boxMin = vec3(-size, -size, -range);
    vec3 boxSize = vec3(2.0 * size, 2.0 * size, range);
    point<light_s> p = point<light_s>(boxMin + corner * boxSize);
    gl_Position = clipFromView * viewFromLight * vec4(p, 1.0);
}
