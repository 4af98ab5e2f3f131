#version 330 core
#include <safegi/prelude.sgl>
// A DirectX toolkit's built-in effect lighting (per-pixel, one directional
// light): the Blinn-Phong lobe is a BRDF like the diffuse term, so the
// specular light is scaled by N.L too, not only cut off where N.L < 0.
space world;

uniform direction<world, toward> LightDirection;       // the way the light travels
uniform spectrum<irradiance / proj> LightDiffuseColor;  // on a surface facing the light
uniform spectrum<irradiance / proj> LightSpecularColor;
uniform spectrum<brdf> DiffuseColor;
uniform spectrum<brdf> SpecularColor;
uniform float SpecularPower;
uniform point<world> EyePosition;

in point<world, shaded> PositionWS;
in normal<world> NormalWS;
out vec4 fragColor;

void main() {
    vec3 worldNormal = normalize(NormalWS);
    vec3 eyeVector = normalize(EyePosition - PositionWS);
    vec3 halfVector = normalize(eyeVector - LightDirection);
    float dotL = dot(worldNormal, -LightDirection);
    float dotH = dot(worldNormal, halfVector);
    float zeroL = step(0.0, dotL);
    float diffuse = zeroL * dotL;
    float specular = pow(max(dotH, 0.0) * zeroL, SpecularPower);
    spectrum<radiance> color = DiffuseColor * LightDiffuseColor * diffuse + SpecularColor * LightSpecularColor * specular;
    fragColor = vec4(color, 1.0);
}
