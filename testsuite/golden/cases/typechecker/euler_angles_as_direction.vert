#version 450
#include <safegi/prelude.sgl>
// A light's Euler angles are rotations about three axes, not the direction the
// light shines: a vec3 of angles beside a vector of a space in dot(), cross()
// or reflect() is refused. Angles alone, and a column of the rotation they
// built, are fine.
space world;

uniform rigidmap<world, world> lightRotation;
uniform vec3<angle> lightEuler;
uniform normal<world> n;

out float shade;

void main() {
    vec3 toLight = -lightRotation[2].xyz;
    float lit = max(dot(n, toLight), 0.0);
    float wrong = max(dot(n, -lightEuler), 0.0);
    vec3 spin = cross(lightEuler, n);
    float yaw = lightEuler.y + lightEuler.x;
    shade = lit + wrong + spin.x + cos(yaw);
}
