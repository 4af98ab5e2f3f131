#version 460
#include <safegi/prelude.sgl>
// Next-event estimation on a sphere light in a Vulkan path tracer for Hydra
// with MDL materials (a closest-hit shader, excerpted as a fragment shader):
// a point is drawn uniformly on the sphere's surface (pdf 1 / (4 pi r^2) per
// area), and the light's radiance reaches the shaded point through the
// geometry term cos(light) / d^2, which turns the per-area estimate into one
// per solid angle. A sphere of radius 0 is a point light.
space world;

const float PI = 3.14159265358979;

uniform point<world> lightPos;
uniform float<length> lightRadius;
uniform spectrum<radiance> lightIntensity;         // UsdLux intensity * color
uniform spectrum<brdf> bsdf;

in point<world, shaded> surfacePos;
flat in normal<world> surfaceNormal;
in vec2 xi;
out vec4 fragColor;

vector<world> sample_sphere(vec2 u, float<length> radius, out float<pdf_area> pdf) {
    float z = 1.0 - 2.0 * u.x;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = 2.0 * PI * u.y;
    pdf = 1.0 / (4.0 * PI * radius * radius);
    return vec3(r * cos(phi), r * sin(phi), z) * radius;
}

void main() {
    float<pdf_area> samplePdf;
    point<world> samplePos = lightPos + sample_sphere(xi, lightRadius, samplePdf);
    vec3 dir = samplePos - surfacePos;
    float dist = length(dir);
    direction<world> dirToLight = normalize(dir);

    float cosTheta = (lightRadius > 0.0) ? max(0.0, dot(normalize(samplePos - lightPos), -dirToLight)) : 1.0;
    float geometryTerm = cosTheta / (dist * dist);

    vec3 power = lightIntensity;
    float pdf = samplePdf * dist * dist; // quad. attenuation

    float cosSurface = max(dot(surfaceNormal, dirToLight), 0.0);
    spectrum<radiance> Lo = bsdf * power * cosSurface / pdf;
    fragColor = vec4(Lo, 1.0);
}
