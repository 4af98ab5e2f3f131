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
    vector<world, away> s = u_lightPosition - v_position;
    float<length> dist = length(s);
    direction<world, away> L = normalize(s);
    direction<world> H = normalize(L + V);
    float<proj> NoL = max(dot(N, L), 0.0);
    float NoV = max(dot(N, V), 1e-4);
    float NoH = max(dot(N, H), 0.0);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (dist * dist));
    spectrum<irradiance / proj> light = u_lightColor * u_lightIntensity * falloff;
    diffuse += light * u_albedo * INV_PI;
    specular += light * specularGGX(NoH, NoV, NoL, u_roughness);
}

void main() {
    normal<world> N = normalize(v_normal);
    direction<world, away> V = normalize(u_camera - v_position);
    spectrum<radiance> diffuse = spectrum<radiance>(0.0);
    spectrum<radiance> specular = spectrum<radiance>(0.0);
    lightPoint(N, V, diffuse, specular);
    fragColor = vec4(diffuse + specular, 1.0);
}
