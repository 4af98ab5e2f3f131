#version 450
#include <safegi/prelude.sgl>
// A ray tracer's instance shading: the hit is found in the instance's object
// space and shaded in world space. The instance transform may scale one axis
// more than another, so the geometric normal goes through the inverse
// transpose (a normal carried by vec4(n, 0.0) * inverse(m)), the hit point
// through the transform itself.
space object;
space world;

uniform map<object, world> instanceXfm;
uniform direction<world> lightDir;                     // toward the light
uniform spectrum<irradiance / proj> lightIrradiance;   // on a surface facing the light
uniform spectrum<brdf> diffuseBrdf;

in point<object> hitObject;
in normal<object> normalObject;
out vec4 fragColor;

void main() {
    vec3 n = normalize((instanceXfm * vec4(normalObject, 0.0)).xyz);
    float cosL = max(dot(n, lightDir), 0.0);
    spectrum<radiance> L = diffuseBrdf * lightIrradiance * cosL;
    fragColor = vec4(L, 1.0);
}
