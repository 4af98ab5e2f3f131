#version 330 core
#include <safegi/prelude.sgl>
// A glTF viewer's metallic-roughness shading under one directional light:
// Lambert plus Cook-Torrance (GGX, Smith, Schlick), lit by the light's
// illuminance on the surface, which the cosine NdotL makes from the one
// facing the light.
space world;

uniform direction<world> u_LightDirection;            // toward the light
uniform spectrum<irradiance / proj> u_LightColor;     // on a surface facing the light
uniform point<world> u_Camera;
uniform spectrum<1> u_BaseColor;
uniform float<1> u_Metallic;
uniform float<1> u_Roughness;

in point<world, shaded> v_Position;
in normal<world> v_Normal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 n = normalize(v_Normal);
    vec3 v = normalize(u_Camera - v_Position);
    vec3 l = normalize(u_LightDirection);
    vec3 h = normalize(l + v);
    float NdotL = clamp(dot(n, l), 0.001, 1.0);
    float NdotV = abs(dot(n, v)) + 0.001;
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    float VdotH = clamp(dot(v, h), 0.0, 1.0);

    float alpha = u_Roughness * u_Roughness;
    vec3 f0 = mix(vec3(0.04), u_BaseColor, u_Metallic);
    vec3 F = f0 + (vec3(1.0) - f0) * pow(1.0 - VdotH, 5.0);
    float a2 = alpha * alpha;
    float G = 2.0 * NdotL / (NdotL + sqrt(a2 + (1.0 - a2) * NdotL * NdotL))
            * 2.0 * NdotV / (NdotV + sqrt(a2 + (1.0 - a2) * NdotV * NdotV));
    float f = (NdotH * a2 - NdotH) * NdotH + 1.0;
    float D = a2 * INV_PI / (f * f);

    vec3 diffuse = (vec3(1.0) - F) * mix(u_BaseColor * 0.96, vec3(0.0), u_Metallic) * INV_PI;
    vec3 specular = F * G * D / (4.0 * NdotL * NdotV);
    spectrum<radiance> color = u_LightColor * (diffuse + specular);
    fragColor = vec4(color, 1.0);
}
