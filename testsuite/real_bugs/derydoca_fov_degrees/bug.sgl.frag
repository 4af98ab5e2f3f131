#version 330 core
#include <safegi/prelude.sgl>
// A camera component whose field of view is set in degrees in the editor;
// primary rays use tan of half the angle, which wants radians.
space world;

uniform float<angle in degree> fieldOfView;         // vertical, as the editor shows it
uniform vec2 resolution;
uniform point<world> cameraPosition;
uniform direction<world> forward;
uniform direction<world> right;
uniform direction<world> up;
uniform samplerCube<spectrum<radiance>> skybox;

out vec4 fragColor;

void main() {
    vec2 ndc = (gl_FragCoord.xy / resolution) * 2.0 - 1.0;
    float aspect = resolution.x / resolution.y;
    float halfHeight = tan(fieldOfView * 0.5);
    vec3 dir = normalize(forward + ndc.x * aspect * halfHeight * right + ndc.y * halfHeight * up);
    spectrum<radiance> L = texture(skybox, dir).rgb;
    fragColor = vec4(L, 1.0);
}
