#version 450
#include <safegi/prelude.sgl>
// A sun's irradiance is measured on a plane facing the sun: irradiance / proj,
// which the receiver's cosine makes the irradiance on the surface. Declared as
// plain irradiance, the product has one proj too many; the hint names the
// declaration beside the other cause, a cosine applied twice.
space world;

uniform spectrum<irradiance / proj> sunFacing;
uniform spectrum<irradiance> sunAsDeclared;
uniform normal<world> n;
uniform direction<world> toSun;

out vec4 color;

void main() {
    float cosSun = max(dot(n, toSun), 0.0);
    spectrum<irradiance> onSurface = sunFacing * cosSun;
    spectrum<irradiance> twice = sunAsDeclared * cosSun;
    color = vec4(onSurface + twice, 1.0);
}
