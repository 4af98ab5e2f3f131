#version 450
#include <safegi/prelude.sgl>
// A terrain plugin's fragment shader: the detail normal map is in a tangent
// frame laid on the terrain, built from the interpolated world normal and the
// world's z axis; the mapped normal is brought to world space and lit by the
// sun.
space world;
space view;
space tangent;

uniform sampler2D normalMap;
uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<brdf> albedo;

in normal<world> worldNormal;
in normal<view> viewNormal;
in vec2 uv;
out vec4 fragColor;

void main() {
    vec3 n = normalize(worldNormal);
    vec3 t = normalize(cross(n, vec3(0.0, 0.0, 1.0)));
    vec3 b = cross(t, n);
    mat3<tangent, world, rigid> tbn = mat3(t, b, n);
    normal<tangent> nt = normalize(texture(normalMap, uv).xyz * 2.0 - 1.0);
    vec3 nw = normalize(tbn * nt);
    float cosL = max(dot(nw, lightDir), 0.0);
    fragColor = vec4(albedo * lightIrradiance * cosL, 1.0);
}
