#version 450
#include <safegi/prelude.sgl>
// A scriptable render pipeline's tree shader, forward pass: the world-space
// vertex normal is interpolated across the triangle, so it is renormalized per
// pixel before the main light's Lambert term.
space world;

uniform direction<world> _MainLightPosition;      // toward the light
uniform spectrum<irradiance / proj> _MainLightColor;

layout(location = 0) in normal<world> normalWS;
layout(location = 1) in spectrum<1> albedo;
layout(location = 0) out vec4 outColor;

const float INV_PI = 0.31830988618;

void main() {
    vec3 n = normalWS;
    float NdotL = max(dot(n, _MainLightPosition), 0.0);
    spectrum<radiance> color = albedo * INV_PI * _MainLightColor * NdotL;
    outColor = vec4(color, 1.0);
}
