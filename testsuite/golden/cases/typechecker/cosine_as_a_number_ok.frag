#version 330 core
#include <safegi/prelude.sgl>
// A cosine used as a number (Schlick, the GGX distribution, Smith masking, a
// Phong lobe) is a plain number; in a product it stays the projection factor.
space world;
uniform normal<world> n;
uniform direction<world> wi;
uniform direction<world> h;
uniform float<1> alpha;
uniform spectrum<1> F0;
uniform spectrum<radiance> Li;
uniform spectrum<brdf> Kd;
out vec4 c;
float<1> smithG1(float<1> cosine, float<1> a2) { return 2.0 * cosine / (cosine + sqrt(a2 + (1.0 - a2) * cosine * cosine)); }
void main() {
  float<proj> cosI = max(dot(n, wi), 0.0);
  float<proj> cosH = max(dot(n, h), 0.0);
  float<1> a2 = alpha * alpha;
  float<1> t = cosH * cosH * (a2 - 1.0) + 1.0;
  spectrum<1> F = F0 + (1.0 - F0) * pow(1.0 - cosI, 5);
  float<1> G = smithG1(cosI, a2);
  float<1> lobe = pow(cosH, 32.0);
  spectrum<radiance> L = Kd * Li * cosI * float<solid_angle>(1.0);
  c = vec4(L * F * G * lobe / t, 1.0);
}
