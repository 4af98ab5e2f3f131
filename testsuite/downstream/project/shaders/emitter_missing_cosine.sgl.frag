#version 330 core
// The same with the cosine forgotten: radiance times solid angle is not irradiance.
#include <safegi/prelude.sgl>

uniform spectrum<radiance> Le;
uniform float<area> emitterArea;
uniform float<length> distanceToReceiver;

out spectrum<irradiance> irradiance;

void main() {
    float<solid_angle> subtended = float<solid_angle>(emitterArea / (distanceToReceiver * distanceToReceiver));
    irradiance = Le * subtended;
}
