#version 330 core
// One sample of a rectangular area light: the light is sampled by area, so
// its pdf is converted to the projected solid angle at the shading point with
// the r^2 / cos Jacobian before it divides the estimate.
#include <safegi/prelude.sgl>

space world;

uniform point<world>       lightCorner;
uniform vector<world>      lightEdgeU;
uniform vector<world>      lightEdgeV;
uniform normal<world>      lightNormal;
uniform spectrum<radiance> Le;
uniform float<area>        lightArea;
uniform spectrum<brdf>     Kd;

in point<world>  P;
in normal<world> N;
in vec2          xi;                       // uniform random numbers

out vec4 fragColor;

void main() {
    point<world> Y = lightCorner + lightEdgeU * xi.x + lightEdgeV * xi.y;
    vector<world> toLight = Y - P;
    float<area> r2 = dot(toLight, toLight);
    direction<world> wi = normalize(toLight);
    float<proj> cosX = max(dot(normalize(N), wi), 0.0);
    float<proj> cosY = max(-dot(normalize(lightNormal), wi), 0.0);
    float<pdf_area> pdfA = 1.0 / lightArea;
    // Area measure at Y -> projected solid angle at P: the r^2 / cos Jacobian,
    // where the cosine at the light turns area into solid angle.
    float<pdf_projected_solid_angle> pdfW = pdfA * r2 / (cosX * float<solid_angle>(cosY));
    spectrum<radiance> L = Kd * Le / pdfW;
    fragColor = vec4(L, 1.0);
}
