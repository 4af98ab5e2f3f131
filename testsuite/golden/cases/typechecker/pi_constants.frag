#version 330 core
#include <safegi/prelude.sgl>
// An unannotated `const float PI = 3.14159…;` is π, whichever quantity its
// use needs of the ones π measures: a plain number (πr²), radians, steradians
// (2π the hemisphere, 4π the sphere) or projected steradians (π the
// cosine-weighted hemisphere, the lobes' 2π and 8π). A declared result that
// no such reading makes is told, with π read as the likeliest one. A local
// holding such a product carries it; π / π cancels; a sum with a known side
// decides what π is there, and two sides that differ whatever π is are told.
uniform spectrum<1> albedo;
uniform float<proj> cosTheta;
uniform float<length> r;
uniform spectrum<irradiance / proj> lightDiffuse;
uniform spectrum<radiance> envRadiance;
const float PI = 3.14159265358979;
const float TWO_PI = 6.28318530717959;
const float INV_PI = 0.318309886183791;
out vec4 c;
void main() {
    spectrum<brdf> lambert = albedo / PI;
    spectrum<brdf> lambertToo = albedo * INV_PI;
    float<pdf_solid_angle> uniformHemisphere = 1.0 / TWO_PI;
    float<pdf_solid_angle> cosineWeighted = cosTheta / PI;
    float<area> disk = PI * r * r;
    float<angle> halfTurn = PI;
    float<pdf_solid_angle> withoutCosine = 1.0 / PI;
    float<area> sphere = 4.0 * PI * r;
    vec3 diffuse = albedo / PI;
    vec3 direct = diffuse * lightDiffuse * cosTheta;
    spectrum<radiance> lit = direct + envRadiance * diffuse * PI;
    spectrum<radiance> litTwice = direct + envRadiance * diffuse;
    c = vec4(lit + litTwice + lambert * (uniformHemisphere + cosineWeighted + withoutCosine) * disk * sphere / (r * r * r * r), halfTurn);
}
