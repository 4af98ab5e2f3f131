#version 330 core
// The shadow map stores the distance from the light to the nearest surface,
// a length, not the rasteriser's non-linear depth: the shading pass compares
// it with its own distance to the light in the same unit.
#include <safegi/prelude.sgl>

space world;

uniform point<world> lightPosition;

in point<world> P;

out float<length> lightDistance;

void main() {
    lightDistance = length(P - lightPosition);
}
