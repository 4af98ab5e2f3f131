#version 330 core
#include <safegi/prelude.sgl>
// A GPU path tracer's next-event estimation on an area light: the point drawn
// uniformly by area has pdf 1/A, converted once to a pdf per solid angle by
// the geometry term r^2 / cos(theta_light).
space world;

uniform point<world> lightSample;                   // drawn uniformly on the emitter
uniform normal<world> lightNormal;
uniform float<area> lightArea;
uniform spectrum<radiance> Le;
uniform spectrum<brdf> bsdf;

in point<world, shaded> P;
in normal<world> N;
out vec4 fragColor;

float<pdf_solid_angle> toSolidAngle(float<pdf_area> pdfA, float<proj> cosLight,
                                    float<solid_angle / (area * proj)> invDist2) {
    return pdfA / (cosLight * invDist2);
}

void main() {
    vec3 toLight = lightSample - P;
    float dist = length(toLight);
    vec3 wi = normalize(toLight);
    float cosLight = max(dot(lightNormal, -wi), 0.0);
    float cosSurface = max(dot(normalize(N), wi), 0.0);
    float invDist2 = float<solid_angle / (area * proj)>(1.0 / (dist * dist));
    float pdfA = 1.0 / lightArea;
    float pdfW = toSolidAngle(pdfA, cosLight, invDist2);
    spectrum<radiance> Ld = bsdf * Le * cosSurface / toSolidAngle(pdfW, cosLight, invDist2);
    fragColor = vec4(Ld, 1.0);
}
