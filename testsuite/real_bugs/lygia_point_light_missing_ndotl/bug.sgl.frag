#version 330 core
#include <safegi/prelude.sgl>
// A shader library's PBR point light: Lambert diffuse and a GGX specular
// lobe, each accumulated as BRDF x irradiance, the irradiance carrying N.L.
space world;

uniform point<world> u_lightPosition;
uniform spectrum<intensity> u_lightColor;
uniform float<1> u_lightIntensity;
uniform point<world> u_camera;
uniform spectrum<1> u_albedo;
uniform float<1> u_roughness;

in point<world, shaded> v_position;
in normal<world> v_normal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.31830988618);

float<brdf> specularGGX(float NoH, float NoV, float NoL, float roughness) {
    float a2 = roughness * roughness * roughness * roughness;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    float vis = 0.5 / (NoL * sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * sqrt(NoL * NoL * (1.0 - a2) + a2) + 1e-5);
    return a2 * INV_PI / (d * d) * vis;
}

void lightPoint(normal<world> N, direction<world, away> V, inout spectrum<radiance> diffuse, inout spectrum<radiance> specular) {
    vec3 s = u_lightPosition - v_position;
    float dist = length(s);
    vec3 L = normalize(s);
    vec3 H = normalize(L + V);
    float NoL = max(dot(N, L), 0.0);
    float NoV = max(dot(N, V), 1e-4);
    float NoH = max(dot(N, H), 0.0);
    float falloff = float<solid_angle / (area * proj)>(1.0 / (dist * dist));
    vec3 light = u_lightColor * u_lightIntensity * falloff;
    diffuse += light * u_albedo * INV_PI;
    specular += light * specularGGX(NoH, NoV, NoL, u_roughness);
}

void main() {
    vec3 N = normalize(v_normal);
    vec3 V = normalize(u_camera - v_position);
    vec3 diffuse = spectrum<radiance>(0.0);
    spectrum<radiance> specular = spectrum<radiance>(0.0);
    lightPoint(N, V, diffuse, specular);
    fragColor = vec4(diffuse + specular, 1.0);
}
