#version 450
#include <safegi/prelude.sgl>
// A sky-atmosphere research renderer's multiple-scattering LUT (an HLSL
// compute shader, rewritten as a GLSL fragment shader): the luminance
// scattered toward a point is integrated over the whole sphere of directions
// on a fixed 8 x 8 grid of (u, v); each direction stands for 4 pi / 64
// steradians, which is only true when the directions are spread uniformly
// over the sphere: the polar angle is acos(1 - 2 v), not pi * v.
space world;

const float PI = 3.14159265358979;

uniform samplerCube<spectrum<radiance>, world> scatteredLuminance;   // stands in for the ray march

out vec4 fragColor;

void main() {
    const float<solid_angle> SphereSolidAngle = 4.0 * PI;
    const float<pdf_solid_angle> IsotropicPhase = 1.0 / SphereSolidAngle;
    const float sqrtSample = 8.0;
    vec3 sum = vec3(0.0);
    for (int k = 0; k < 64; k++) {
        float randA = (0.5 + float(k / 8)) / sqrtSample;
        float randB = (0.5 + float(k % 8)) / sqrtSample;
        float theta = 2.0 * PI * randA;
        float phi = PI * randB;
        vec3 dir = vec3(cos(theta) * sin(phi), sin(theta) * sin(phi), cos(phi));
        spectrum<radiance> L = texture(scatteredLuminance, dir).rgb;
        sum += L * SphereSolidAngle / (sqrtSample * sqrtSample);
    }
    spectrum<radiance> Lms = sum * IsotropicPhase;
    fragColor = vec4(Lms, 1.0);
}
