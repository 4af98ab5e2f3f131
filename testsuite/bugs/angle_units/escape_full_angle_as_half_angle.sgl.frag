#version 330 core
#include <safegi/prelude.sgl>
// A spot light's cone: angles in, numbers out.
space world;

uniform point<world> lightPos;
uniform direction<world> spotAxis;
uniform float<angle> spotAngle;
uniform spectrum<radiance> Le;

in point<world> P;
out vec4 fragColor;

void main() {
    float<angle> halfAngle = spotAngle;
    float s = sin(halfAngle);
    float c = cos(halfAngle);
    direction<world> toP = normalize(P - lightPos);
    float cosToAxis = dot(toP, spotAxis);
    float inside = 0.0;
    if (cosToAxis > c)
        inside = smoothstep(c, 1.0, cosToAxis) * (1.0 - s * s);
    fragColor = vec4(Le * inside, 1.0);
}
