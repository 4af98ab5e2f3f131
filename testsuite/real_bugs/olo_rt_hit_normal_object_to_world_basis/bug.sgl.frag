#version 460
#include <safegi/prelude.sgl>
// A game engine's ray-traced reflections: at the instance a reflection ray
// hit, the triangle's object-space normal is brought to world space by the
// inverse transpose of the instance transform, written as the normal times
// the world-to-object matrix the ray query also returns (no inverse needed).
space object;
space world;

uniform map<object, world> objectToWorld;         // the hit instance's transform
uniform map<world, object> worldToObject;         // its inverse, from the ray query
uniform direction<world> sunDirection;            // toward the sun
uniform spectrum<irradiance / proj> sunIrradiance;

flat in normal<object> hitObjectNormal;           // interpolated by barycentrics already
in spectrum<brdf> hitDiffuse;
layout(location = 0) out vec4 reflectionOut;

void main() {
    normal<world> n = normalize(mat3(objectToWorld) * hitObjectNormal);
    float cosSun = max(dot(n, sunDirection), 0.0);
    spectrum<radiance> L = hitDiffuse * sunIrradiance * cosSun;
    reflectionOut = vec4(L, 1.0);
}
