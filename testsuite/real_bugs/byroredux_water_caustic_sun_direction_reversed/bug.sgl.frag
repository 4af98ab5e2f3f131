#version 450
#include <safegi/prelude.sgl>
// A renderer's water surface synthesises caustics: sunlight refracted at the
// surface is followed down to the floor, weighted by the surface's Lambert
// cosine. The camera block's sun vector points toward the sun (the shadow
// ray of the opaque pass fires along it); the refraction needs the direction
// the light travels, its negation.
space world;

uniform direction<world, away> sunDirection;      // toward the sun
uniform spectrum<irradiance> sunIrradiance;       // on a plane facing the sun
uniform float<length> floorDepth;                 // water depth below the surface

in point<world, shaded> surfacePos;
in normal<world> surfaceNormal;
out point<world> causticHit;
out vec4 causticIrradiance;

void main() {
    normal<world> N = normalize(surfaceNormal);
    float cosSun = max(dot(N, -sunDirection), 0.0);
    vec3 refracted = refract(sunDirection, N, 1.0 / 1.33);
    float<length> t = floorDepth / max(-refracted.y, 1e-3);
    causticHit = surfacePos + refracted * t;
    spectrum<irradiance> E = sunIrradiance * cosSun;
    causticIrradiance = vec4(E, 1.0);
}
