#version 330 core
#include <safegi/prelude.sgl>
// Quantities written down with their units; all arithmetic in reference units.
out vec4 fragColor;

void main() {
    float<length> radius = 5.0 * millimeter;
    float<length> near = 0.1 * meter;
    float<time> shutter = 20.0 * millisecond;
    float<angle> fov = 60.0 * degree;
    float<velocity> speed = (radius + near) / shutter;
    fragColor = vec4(vec3(speed * second / meter, tan(0.5 * fov), 1.0), 1.0);
}
