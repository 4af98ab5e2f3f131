#version 330 core
#include <safegi/prelude.sgl>
// A point light carried from a modelling tool (power in watts) into a glTF
// viewer's shading, which takes a punctual light's intensity per steradian:
// an isotropic point light spreads its power over the full sphere, so the
// intensity is the power over 4 pi sr (times the luminous efficacy, 683 lm/W,
// where the viewer works in photometric units).
space world;

uniform point<world> u_LightPosition;
uniform float<power> u_LightPowerWatts;
uniform spectrum<1> u_LightColor;
uniform spectrum<brdf> u_Diffuse;

in point<world, shaded> v_Position;
in normal<world> v_Normal;
out vec4 fragColor;

const float<solid_angle> FULL_SPHERE = float<solid_angle>(4.0 * 3.141592653589793);
const float<1> LUMENS_PER_WATT = 683.0;

void main() {
    vec3 intensity = u_LightColor * u_LightPowerWatts * LUMENS_PER_WATT / FULL_SPHERE;
    vec3 toLight = u_LightPosition - v_Position;
    float<length> d = length(toLight);
    vec3 l = normalize(toLight);
    vec3 n = normalize(v_Normal);
    float NdotL = max(dot(n, l), 0.0);
    spectrum<radiance> color = u_Diffuse * intensity * inverse_square(d) * NdotL;
    fragColor = vec4(color, 1.0);
}
