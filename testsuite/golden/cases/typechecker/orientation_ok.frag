#version 330 core
#include <safegi/prelude.sgl>
// Orientation flows through negation, normalize, sums of like directions,
// scaling, transforms and reflect; unoriented values fit either way; a cast
// states a new orientation (a direction flipped into the normal's hemisphere).
space world;
space object;
uniform point<world> lightPos;
uniform point<world> eyePos;
uniform normal<world> n;
uniform rigidmap<object, world> worldFromObject;
uniform direction<world> sampled;                  // unoriented
in point<object, shaded> position;
out vec4 c;
direction<world, toward> incident(direction<world, away> w) { return -w; }
void main() {
  point<world, shaded> P = worldFromObject * position;
  point<world, shaded> origin = P + 0.001 * meter * n;
  vector<world, away> toLight = lightPos - origin;
  direction<world, away> wi = normalize(toLight);
  direction<world, away> wo = normalize(eyePos - P);
  direction<world, away> h = normalize(wi + wo);
  vector<world, away> scaled = 2.0 * toLight;
  vector<world, toward> flipped = -1.0 * toLight;
  direction<world, away> mirror = reflect(incident(wo), n);
  direction<world, away> refracted = refract(-wo, n, 0.75);
  direction<world, toward> along = dot(sampled, n) > 0.0 ? -wi : -wo;
  direction<world, away> anyWay = sampled;
  direction<world, away> hemisphere = direction<world, away>(dot(sampled, n) < 0.0 ? -sampled : sampled);
  c = vec4(h + mirror + refracted + along + anyWay + hemisphere + scaled / meter + flipped / meter, 1.0);
}
