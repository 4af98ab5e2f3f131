#version 330 core
#include <safegi/prelude.sgl>
// A volumetric-clouds post-process for a game engine: the sun's colour, the
// sky's tint and the fog's light follow the sun's elevation, the z (up)
// component of the unit direction toward the sun. The engine hands the
// shader the sun's offset from the viewer, which is not unit length, so the
// direction is normalized once and its z used everywhere.
space world;

uniform vector<world> sunPos;           // the sun's offset from the viewer
uniform vec3 sky_tone;
in direction<world> dir;                // the pixel's view ray
in float max_dist;
out vec4 fragColor;

void main() {
    vec3 sun_dir = normalize(sunPos);

    vec3 sun_color = mix(vec3(2.0, 0.5, 0.2) * 3.0, vec3(0.6, 0.5, 0.0),
                         pow(max(sunPos.z + 0.2, 0.001), 0.1));
    vec3 sky_color = mix(mix(vec3(1.2, 0.4, 0.2), vec3(0.01, 0.05, 0.1),
                             pow(max(-sunPos.z + 0.2, 0.001), 0.2)),
                         vec3(0.6, 0.8, 1.0), sqrt(max(sunPos.z, 0.001))) * sky_tone;

    float sun_light = pow(max(sunPos.z + 0.35, 0.0), 1.0) * 1.3;
    float moon_light = max(0.5 - sunPos.z, 0.0) * 0.3;
    float direct_light = pow(max(dot(dir, sun_dir), 0.0), 50.0)
        * max(sunPos.z, 0.0) * 3.0
        * min(max_dist * (1.0 / 100000.0), 1.0);
    vec3 fog_color = (sun_light + moon_light) * mix(sky_color, sky_tone, max(sunPos.z, 0.3));
    fragColor = vec4(fog_color + direct_light * sun_color, 1.0);
}
