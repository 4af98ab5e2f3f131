#version 300 es
#include <safegi/prelude.sgl>
// A glTF viewer's PBR fragment shader without a normal map: the vertex
// normals are interpolated across the triangle and lose their unit length,
// so the fragment renormalises before any cosine is taken.
precision highp float;
space world;

uniform direction<world> u_LightDirection;            // toward the light
uniform spectrum<irradiance / proj> u_LightColor;
uniform point<world> u_Camera;
uniform spectrum<brdf> u_Diffuse;                     // albedo / pi
uniform spectrum<brdf> u_SpecularPeak;
uniform float u_Shininess;

in point<world, shaded> v_Position;
in normal<world> v_Normal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(v_Normal);
    vec3 v = normalize(u_Camera - v_Position);
    vec3 h = normalize(u_LightDirection + v);
    float NdotL = clamp(dot(n, u_LightDirection), 0.001, 1.0);
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    vec3 f = u_Diffuse + u_SpecularPeak * pow(NdotH, u_Shininess);
    spectrum<radiance> color = NdotL * u_LightColor * f;
    fragColor = vec4(color, 1.0);
}
