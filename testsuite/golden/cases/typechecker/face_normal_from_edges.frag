#version 450
#include <safegi/prelude.sgl>
// The unit cross product of two vectors of a surface (a triangle's edges, the
// screen derivatives of a position) is the surface's normal: it goes where a
// normal<S> is expected without a cast, and transforms as one. Its side is
// whichever the order of the factors gives. Used as a direction, it is
// converted explicitly.
space world;

uniform point<world> p0;
uniform point<world> p1;
uniform point<world> p2;
uniform direction<world, away> toLight;

in point<world> P;
out vec4 color;

void main() {
    normal<world> face = normalize(cross(p1 - p0, p2 - p0));
    vec3 edges = cross(dFdx(P), dFdy(P));
    normal<world> screen = normalize(edges);
    float<proj> cosine = max(dot(face, toLight), 0.0) + max(dot(screen, toLight), 0.0);
    direction<world> along = normalize(cross(p1 - p0, p2 - p0));
    color = vec4(cosine, along);
}
