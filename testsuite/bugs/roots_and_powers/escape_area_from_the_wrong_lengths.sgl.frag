#version 330 core
#include <safegi/prelude.sgl>
// A disk light's radius from its area, and its squared radius back.
uniform float<area> lightArea;
uniform float<length> radius0;
uniform float<1> shininess;

out vec4 fragColor;

void main() {
    float<length> radius = sqrt(lightArea);
    float<area> r2 = radius * radius0;
    float<1> ratio = r2 / lightArea + radius0 / radius;
    float<1> lobe = pow(ratio, shininess);
    fragColor = vec4(vec3(lobe), 1.0);
}
