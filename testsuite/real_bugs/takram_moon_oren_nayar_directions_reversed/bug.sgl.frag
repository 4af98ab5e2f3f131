#version 300 es
#include <safegi/prelude.sgl>
// Physical sky of a three.js add-on (a WebGPU node shader, rewritten as GLSL):
// the moon is a sphere of small angular radius lit by the sun. Where a view ray
// hits it, an Oren-Nayar diffuse term is evaluated with the direction toward
// the sun and the direction back toward the viewer, both pointing away from
// the lit point on the moon's surface.
precision highp float;
space ecef;

uniform direction<ecef, away> sunDirection;       // toward the sun
uniform direction<ecef> moonDirection;            // toward the moon's centre
uniform float<angle> moonAngularRadius;
uniform vec3 moonColor;

in direction<ecef, toward> rayDirection;          // from the eye into the sky
out vec4 fragColor;

// distance to the sphere along the ray, the sphere's centre at unit distance
float intersectSphere(direction<ecef> centerDirection, direction<ecef> rayDir, float<angle> angularRadius) {
    float cosRay = dot(centerDirection, rayDir);
    float discriminant = cosRay * cosRay - pow(cos(angularRadius), 2.0);
    return cosRay - sqrt(discriminant);
}

float orenNayarDiffuse(direction<ecef, away> L, direction<ecef, away> V, direction<ecef> N) {
    float NdotL = dot(N, L);
    float NdotV = dot(N, V);
    float s = dot(L, V) - NdotL * NdotV;
    float t = s > 0.0 ? max(NdotL, NdotV) : 1.0;
    const float sigma2 = 0.09;
    float A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    return max(NdotL, 0.0) * (A + B * s / t);
}

void main() {
    vec3 color = vec3(0.0);
    float intersection = intersectSphere(moonDirection, rayDirection, moonAngularRadius);
    if (intersection > 0.0) {
        vec3 n = normalize(rayDirection * intersection - moonDirection);
        float diffuse = orenNayarDiffuse(-sunDirection, rayDirection, n);
        color = moonColor * diffuse;
    }
    fragColor = vec4(color, 1.0);
}
