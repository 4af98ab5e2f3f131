#version 330 core
#include <safegi/prelude.sgl>
// A disk light whose scene file gives its radius in centimetres and its cone in
// degrees; quantities are converted once, where they enter, into reference units.
space world;

uniform float<length in centimeter> lightRadiusCm;    // as the scene file writes it
uniform float<angle in degree> coneHalfAngleDeg;
uniform point<world> lightCenter;
uniform normal<world> lightNormal;
uniform direction<world> lightTangent;                // the disk's frame
uniform direction<world> lightBitangent;
uniform spectrum<radiance> Le;
uniform spectrum<brdf> Kd;
uniform vec2<1> xi;                                   // two uniform random numbers

in point<world> P;
in normal<world> N;
out vec4 fragColor;

const float<1> PI = 3.14159265358979;

void main() {
    float<length> radius = lightRadiusCm;
    float<proj> cosCone = float<proj>(cos(coneHalfAngleDeg in radian));  // compared with cosLight
    // A point on the disk: radius r·√ξ₀ at azimuth φ = 2π·ξ₁.
    float<angle> phi = 2.0 * PI * xi.y * radian;
    float<length> r = radius * sqrt(xi.x);
    point<world> y = lightCenter + lightTangent * (r * cos(phi)) + lightBitangent * (r * sin(phi));
    vector<world> toY = y - P;
    float<length> dist = length(toY);
    direction<world> wy = normalize(toY);
    float<proj> cosSurface = max(dot(normalize(N), wy), 0.0);
    float<proj> cosLight = max(dot(-wy, lightNormal), 0.0);
    float<area> lightArea = PI * radius * radius;
    float<pdf_solid_angle> pdfW = float<pdf_solid_angle>(dist * dist / (lightArea * cosLight));
    float inCone = step(cosCone, cosLight);
    spectrum<radiance> L = Kd * Le * cosSurface * inCone / pdfW;
    fragColor = vec4(L, 1.0);
}
