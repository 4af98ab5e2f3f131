#version 460
#include <safegi/prelude.sgl>
// Next-event estimation on a rectangular area light in a Vulkan path tracer
// for Hydra (a closest-hit shader, excerpted as a fragment shader): a point is
// drawn uniformly on the rectangle, spanned from its centre by the light's two
// tangent axes, and its radiance reaches the shaded point through
// cos(light) / d^2 over the area pdf 1 / (width * height). The light faces
// along cross(t1, t0), -Z of its frame as in UsdLux.
space world;

uniform point<world> lightOrigin;
uniform direction<world> t0;                       // the light's tangent frame
uniform direction<world> t1;
uniform float<length> lightWidth;
uniform float<length> lightHeight;
uniform spectrum<radiance> lightIntensity;
uniform spectrum<brdf> bsdf;

in point<world, shaded> surfacePos;
flat in normal<world> surfaceNormal;
in vec2 xi;
out vec4 fragColor;

void main() {
    vec2<length> sampleOnRect = (xi - 0.5) * vec2<length>(lightWidth, lightHeight);
    normal<world> lightNormal = normal<world>(cross(t1, t0));
    point<world> samplePos = lightOrigin + vec3(sampleOnRect, 0.0) * lightNormal;

    vec3 dir = samplePos - surfacePos;
    float dist = length(dir);
    direction<world> dirToLight = normalize(dir);

    float geometryTerm = max(0.0, dot(lightNormal, -dirToLight)) / (dist * dist);
    vec3 power = lightIntensity * geometryTerm;
    float<pdf_area> pdf = 1.0 / (lightWidth * lightHeight);

    float cosSurface = max(dot(surfaceNormal, dirToLight), 0.0);
    spectrum<radiance> Lo = bsdf * power * cosSurface / pdf;
    fragColor = vec4(Lo, 1.0);
}
