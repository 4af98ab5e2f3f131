#version 300 es
#include <safegi/prelude.sgl>
// A WebGL path tracer's direct lighting from a rectangular area light (a quad
// on a ceiling): one point is drawn uniformly on the quad, and its radiance
// reaches the diffuse surface through the geometry term
// cos(light) * cos(surface) * A / d^2, a projected solid angle per sample.
precision highp float;
space world;

uniform spectrum<radiance> lightEmission;
uniform normal<world> lightNormal;               // faces down into the room
uniform float<area> lightArea;                   // |v1 - v0| * |v3 - v0|
uniform point<world> lightSample;                // uniform on the quad

in point<world, shaded> x;
in normal<world> nl;
in spectrum<brdf> diffuseBrdf;                   // albedo / pi
out vec4 fragColor;

void main() {
    vec3 toLight = lightSample - x;
    float d = length(toLight);
    direction<world> srDir = normalize(toLight);
    float nlDotSrDir = dot(normalize(nl), srDir);
    vec3 dirLight = vec3(0.0);
    if (nlDotSrDir > 0.01) {
        float cosLight = max(dot(-srDir, lightNormal), 0.0);
        float<projected_solid_angle> weight = cosLight * nlDotSrDir * lightArea * inverse_square(d);
        spectrum<radiance> L = diffuseBrdf * lightEmission * weight;
        dirLight = L;
    }
    fragColor = vec4(dirLight, 1.0);
}
