#version 330
#include <safegi/prelude.sgl>
// A small PBR pipeline's directional light: the cosines are clamped to
// [0, 1]. With a floor of 0.001 a light behind the surface still gets a
// tiny cosine, and the visibility term G / (4 n.l n.v), divided by it, turns
// that into a visible specular highlight on the unlit side.
space world;

uniform direction<world> lightDir;                 // toward the light
uniform spectrum<irradiance / proj> lightE;        // on a surface facing the light
uniform spectrum<brdf> diffuseBrdf;
uniform spectrum<1> F0;
uniform float alphaRoughness;
uniform point<world> cameraPos;

in point<world, shaded> vPosition;
in normal<world> vNormal;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    direction<world, away> v = normalize(cameraPos - vPosition);
    direction<world> h = normalize(lightDir + v);
    float<proj> n_dot_l = clamp(dot(n, lightDir), 0.0, 1.0);
    float<proj> n_dot_v = clamp(abs(dot(n, v)), 0.001, 1.0);
    float<proj> n_dot_h = clamp(dot(n, h), 0.0, 1.0);
    float v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    float a2 = alphaRoughness * alphaRoughness;
    float f = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    float D = a2 / (3.14159265 * f * f);
    spectrum<1> F = F0 + (spectrum<1>(1.0) - F0) * pow(1.0 - v_dot_h, 5.0);
    float k = alphaRoughness * 0.5;
    float G = n_dot_l / (n_dot_l * (1.0 - k) + k) * (n_dot_v / (n_dot_v * (1.0 - k) + k));
    float Vis = G / (4.0 * n_dot_l * n_dot_v + 0.0001);
    spectrum<brdf> spec = F * float<brdf>(D * Vis);
    spectrum<radiance> L = (diffuseBrdf + spec) * lightE * n_dot_l;
    fragColor = vec4(L, 1.0);
}
