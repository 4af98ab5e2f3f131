#version 330 core
#include <safegi/prelude.sgl>
// Map renderer, directional light whose origin is the world: shading happens
// in eye space, so the light's direction is carried there by the view's
// normal matrix.
space world;
space eye;

uniform direction<world> u_lightDirection;               // the direction light travels
uniform mat3<world, eye, normal> u_normalMatrix;
uniform vec3 u_lightDiffuse;

in normal<eye> v_normal;
in vec4 v_color;
out vec4 fragColor;

void main() {
    vec3 normal = normalize(v_normal);
        float nDotL = max(dot(normal, -u_lightDirection), 0.0);
    vec3 lit = v_color.rgb * u_lightDiffuse * nDotL;
    fragColor = vec4(lit, v_color.a);
}
