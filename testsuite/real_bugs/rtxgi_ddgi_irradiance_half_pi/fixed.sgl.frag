#version 330 core
#include <safegi/prelude.sgl>
// A dynamic-diffuse-GI probe: each probe texel blends the radiance of the
// probe's rays weighted by their cosine to the texel's direction and divides
// by twice the sum of the weights; reading the probe back multiplies by the
// 2 pi of the hemisphere the estimate integrates over, which leaves the
// irradiance (pi times the cosine-weighted mean radiance).
space world;

const int RAYS = 64;
const float<projected_solid_angle> TWO_PI = float<projected_solid_angle>(6.283185307179586);

uniform direction<world> rayDirections[RAYS];
uniform spectrum<radiance> rayRadiance[RAYS];
uniform spectrum<1> albedo;

in direction<world> texelDirection;
out vec4 fragColor;

void main() {
    vec3 weightedSum = vec3(0.0);
    float weightSum = 0.0;
    for (int r = 0; r < RAYS; r++) {
        float weight = max(0.0, dot(texelDirection, rayDirections[r]));
        weightedSum += rayRadiance[r] * weight;
        weightSum += weight;
    }
    vec3 probeValue = weightedSum / max(2.0 * weightSum, 1e-4);
    spectrum<irradiance> irradiance = probeValue * TWO_PI;
    spectrum<radiant_exitance> diffuse = albedo * irradiance;
    fragColor = vec4(diffuse, 1.0);
}
