#version 330 core
#include <safegi/prelude.sgl>
// A glTF viewer's Disney diffuse: Schlick-like retro-reflection terms with
// (1 - N.V)^5; N.V is offset to avoid a division by zero and must stay at
// most 1, or the base of the power turns negative.
space world;

uniform point<world> u_Camera;
uniform direction<world> u_LightDirection;
uniform spectrum<irradiance / proj> u_LightColor;
uniform spectrum<1> diffuseColor;
uniform float<1> alphaRoughness;

in point<world, shaded> v_Position;
in normal<world> v_Normal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 n = normalize(v_Normal);
    vec3 v = normalize(u_Camera - v_Position);
    vec3 l = normalize(u_LightDirection);
    vec3 h = normalize(l + v);
    float NdotL = max(dot(n, l), 0.0);
    float NdotV = abs(dot(n, v)) + 0.001;
    float LdotH = max(dot(l, h), 0.0);
    float f90 = 2.0 * LdotH * LdotH * alphaRoughness - 0.5;
    vec3 diffuse = diffuseColor * INV_PI * (1.0 + f90 * pow(1.0 - NdotL, 5.0)) * (1.0 + f90 * pow(1.0 - NdotV, 5.0));
    spectrum<radiance> color = NdotL * u_LightColor * diffuse;
    fragColor = vec4(color, 1.0);
}
