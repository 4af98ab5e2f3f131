#version 330 core
// The radiance an area light sends toward the eye, and the irradiance it gives
// a receiver: E = Le · cos θ · A / r² (a small emitter).
#include <safegi/prelude.sgl>

uniform spectrum<radiance> Le;
uniform float<area> emitterArea;
uniform float<length> distanceToReceiver;
uniform float<proj> cosTheta;

out spectrum<irradiance> irradiance;

void main() {
    float<solid_angle> subtended = float<solid_angle>(emitterArea / (distanceToReceiver * distanceToReceiver));
    irradiance = Le * cosTheta * subtended;
}
