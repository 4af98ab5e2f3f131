#version 460
#include <safegi/prelude.sgl>
// A Vulkan path tracer's Lambertian scatter (a ray-tracing closest-hit shader,
// excerpted as a fragment shader): half of the time the next ray is aimed at a
// point drawn uniformly on the quad area light, and the path weight is
// brdf / pdf, the Lambertian 1/pi over the light's pdf per solid angle
// d^2 / (cos(light) * A). The ray generation shader multiplies the radiance
// the ray then finds by albedo * weight.
space world;

const float M_1_PI = 0.318309886183791;

uniform point<world> p0;                           // the quad's corners
uniform point<world> p1;
uniform point<world> p3;
uniform normal<world> lightNormal;
uniform float<area> lightArea;
uniform spectrum<radiance> lightEmit;

in point<world, shaded> worldPos;
flat in normal<world> normal;                      // the hit normal, not interpolated here
in spectrum<1> albedo;
in vec2 rnd;
out vec4 fragColor;

void main() {
    point<world> lightpos = p0 + (p1 - p0) * rnd.x + (p3 - p0) * rnd.y;
    vec3 tolight = lightpos - worldPos;
    float ndotl = dot(tolight, normal);
    vec3 color = vec3(0.0);
    if (ndotl >= 0.0) {
        float dist = length(tolight);
        direction<world> wi = normalize(tolight);
        const float epsVariance = 0.01;
        float cosine = max(dot(lightNormal, -wi), epsVariance);
        float<pdf_solid_angle> light_pdf = dist * dist / (cosine * lightArea);
        float weight = M_1_PI / light_pdf;
        spectrum<radiance> L = albedo * weight * lightEmit;
        color = L;
    }
    fragColor = vec4(color, 1.0);
}
