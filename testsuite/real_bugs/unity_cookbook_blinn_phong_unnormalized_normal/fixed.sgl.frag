#version 330 core
#include <safegi/prelude.sgl>
// A cookbook's Blinn-Phong lighting function: the interpolated normal is no
// longer of unit length between vertices, so it is normalized before the
// diffuse and half-vector cosines are taken (otherwise the shading looks
// faceted, "per vertex").
space world;

uniform direction<world> lightDir;                  // toward the light
uniform spectrum<irradiance / proj> lightColor;     // on a surface facing the light
uniform spectrum<brdf> diffuseBrdf;
uniform spectrum<brdf> specularBrdf;
uniform float specPower;
uniform point<world> cameraPos;

in point<world, shaded> vPosition;
in normal<world> vNormal;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    direction<world, away> v = normalize(cameraPos - vPosition);
    direction<world> h = normalize(lightDir + v);
    float<proj> diff = max(dot(n, lightDir), 0.0);
    float nh = max(dot(n, h), 0.0);
    float spec = pow(nh, specPower);
    spectrum<radiance> L = (diffuseBrdf + specularBrdf * spec) * lightColor * diff;
    fragColor = vec4(L, 1.0);
}
