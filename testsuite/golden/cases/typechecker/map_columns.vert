#version 330 core
#include <safegi/prelude.sgl>
// The columns of an affine map<A, B>: m[0] … m[2] are A's axes as vectors of
// B (unit directions under a rigidmap), m[3] is A's origin as a point of B.
// The camera's position and forward axis read off its camera-to-world map;
// the origin taken for an axis, or a column of the other map, is told.
space world;
space view;
uniform rigidmap<view, world> worldFromView;
uniform map<world, view> viewFromWorld;
uniform mat3<view, world> rotationToWorld;
in point<world> position;
in normal<world> normalIn;
out vec4 c;
void main() {
    point<world> eye = worldFromView[3].xyz;
    direction<world> back = worldFromView[2].xyz;
    vector<world, 1> right = rotationToWorld[0];
    float<proj> facing = dot(normalIn, normalize(eye - position));
    float along = dot(back, normalize(right));
    vec3 forward = normalize(viewFromWorld[3].xyz);
    float wrongSpace = dot(normalIn, normalize(viewFromWorld[2].xyz));
    c = vec4(facing, along, wrongSpace, 1.0);
    gl_Position = vec4(position, 1.0);
}
