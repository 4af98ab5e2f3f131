#version 330 core
#include <safegi/prelude.sgl>
// An engine's ambient lighting from an equirectangular environment atlas:
// the world normal (interpolated, perturbed) is normalised before it is
// converted to spherical coordinates, where asin/acos need a unit vector.
space world;

uniform sampler2D<spectrum<radiance>> texture_envAtlas;
uniform spectrum<1> dAlbedo;

in normal<world> vNormalW;
out vec4 fragColor;

const float PI = 3.141592653589793;

vec2 toSphericalUv(vec3 dir) {
    float u = atan(dir.x, dir.z) / (2.0 * PI) + 0.5;
    float v = asin(clamp(dir.y, -1.0, 1.0)) / PI + 0.5;
    return vec2(u, v);
}

void main() {
    vec3 dir = normalize(vNormalW * vec3(-1.0, 1.0, 1.0));
    vec2 uv = toSphericalUv(dir);
    spectrum<radiance> ambient = texture(texture_envAtlas, uv).rgb;
    fragColor = vec4(dAlbedo * ambient, 1.0);
}
