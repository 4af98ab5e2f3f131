#version 330 core
#include <safegi/prelude.sgl>
// A heightmap library's ambient occlusion (C in the original): along each of
// a few azimuths the heightmap is marched to find the horizon, the steepest
// direction to the terrain around the point; the occluded share of that
// slice of sky is the horizon's elevation over a right angle, pi / 2 minus
// its angle to the zenith, divided by pi / 2.
const float HALF_PI = 1.5707963267949;
const int DIRECTIONS = 16;
const int STEPS = 32;

uniform sampler2D heightmap;                 // heights in metres
uniform float<length> texelSpacing;          // metres between heightmap texels
uniform vec2 invResolution;

in vec2 uv;
out vec4 fragColor;

void main() {
    vec3 zenith = vec3(0.0, 0.0, 1.0);
    float<length> h0 = texture(heightmap, uv).r * meter;
    float occlusion = 0.0;
    for (int d = 0; d < DIRECTIONS; d++) {
        float phi = 6.283185307179586 * float(d) / float(DIRECTIONS);
        vec2 dir = vec2(cos(phi), sin(phi));
        vec3 horizon = vec3(dir, 0.0);
        for (int s = 1; s <= STEPS; s++) {
            float<length> dh = texture(heightmap, uv + dir * float(s) * invResolution).r * meter - h0;
            vec3 candidate = normalize(vec3(dir * float(s) * texelSpacing, dh));
            if (candidate.z > horizon.z) {
                horizon = candidate;
            }
        }
        occlusion += (HALF_PI - acos(dot(horizon, zenith))) / HALF_PI;
    }
    fragColor = vec4(vec3(1.0 - occlusion / float(DIRECTIONS)), 1.0);
}
