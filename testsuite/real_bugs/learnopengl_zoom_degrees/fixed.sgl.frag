#version 330 core
#include <safegi/prelude.sgl>
// A tutorial camera's zoom is its vertical field of view in degrees (the
// scroll wheel changes it by whole degrees); the perspective it builds needs
// the angle in radians. Here as a full-screen pass that casts the view rays.
space view;

uniform float<angle in degree> zoom;
uniform vec2 viewport;
uniform samplerCube<spectrum<radiance>, view> sky;

out vec4 FragColor;

void main() {
    vec2 ndc = gl_FragCoord.xy / viewport * 2.0 - 1.0;
    float tanHalf = tan(radians(zoom) / 2.0);
    float aspect = viewport.x / viewport.y;
    direction<view> ray = normalize(vec3(ndc.x * aspect * tanHalf, ndc.y * tanHalf, -1.0));
    spectrum<radiance> L = texture(sky, ray).rgb;
    FragColor = vec4(L, 1.0);
}
