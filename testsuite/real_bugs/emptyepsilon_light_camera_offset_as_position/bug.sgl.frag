#version 330 core
#include <safegi/prelude.sgl>
// A space-bridge simulator's model shader: the scene's point lights are
// stored as offsets from the camera, not as world positions, so the light's
// world position is the camera position plus that offset.
space world;

uniform point<world> cameraPosition;
uniform vector<world> lightOffset;               // light position relative to the camera
uniform spectrum<intensity> lightIntensity;
uniform spectrum<1> albedo;

in point<world, shaded> fragWorldPosition;
in normal<world> fragNormal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(fragNormal);
    vec3 lightPosition = lightOffset;
    vec3 toLight = lightPosition - fragWorldPosition;
    float d = length(toLight);
    vec3 L = normalize(toLight);
    spectrum<irradiance> E = lightIntensity * inverse_square(d) * max(dot(N, L), 0.0);
    spectrum<radiance> Lo = albedo * INV_PI * E;
    fragColor = vec4(Lo, 1.0);
}
