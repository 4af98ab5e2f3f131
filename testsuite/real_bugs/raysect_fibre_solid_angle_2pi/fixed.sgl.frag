#version 330 core
#include <safegi/prelude.sgl>
// A ray tracer's optical-fibre observer: rays leave the fibre tip uniformly
// within its acceptance cone, so the Monte Carlo estimate of the collected
// power weights each radiance sample by its cosine, the tip's area and the
// solid angle of the cone that was sampled (not of the whole hemisphere).
space fibre : frame;                                  // z along the fibre axis

uniform float<angle> acceptanceAngle;
uniform float<area> fibreArea;
uniform samplerCube<spectrum<radiance>, fibre> incoming;
uniform int sampleCount;

in vec2 seed;
out vec4 collected;

direction<fibre> sampleCone(float<1> u1, float<1> u2, float<1> cosMax) {
    float cosTheta = 1.0 - u1 * (1.0 - cosMax);
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    float phi = 6.283185307179586 * u2;
    return direction<fibre>(vec3(cos(phi) * sinTheta, sin(phi) * sinTheta, cosTheta));
}

void main() {
    float cosMax = cos(acceptanceAngle);
    float<solid_angle> sampledSolidAngle = float<solid_angle>(6.283185307179586 * (1.0 - cosMax));
    spectrum<power> sum = spectrum<power>(0.0);
    for (int i = 0; i < sampleCount; i++) {
        direction<fibre> w = sampleCone(fract(seed.x + float(i) * 0.618034), fract(seed.y + float(i) * 0.414214), cosMax);
        spectrum<radiance> L = texture(incoming, w).rgb;
        sum += L * w.z * fibreArea * sampledSolidAngle;
    }
    spectrum<power> power = sum / float(sampleCount);
    collected = vec4(power, 1.0);
}
