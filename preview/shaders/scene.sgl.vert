#version 330 core
// Object-space geometry to world space for shading and to the camera's clip
// space for the rasteriser. Shared by every pass that sees the scene through
// the camera, so that their depths agree exactly. A mirror's reflection pass
// sees it through the mirror (clipFromWorld includes the reflection) and cuts
// away what lies behind the mirror's plane (gl_ClipDistance, enabled there only).
#include <safegi/prelude.sgl>

space object;
space world;
space clip;

uniform map<object, world>   worldFromObject;
uniform projmap<world, clip> clipFromWorld;
uniform normal<world>        clipNormal;   // the mirror's plane, its normal towards the camera
uniform point<world>         clipPoint;    // a point on it

layout(location = 0) in point<object>  position;
layout(location = 1) in normal<object> objectNormal;

out point<world>  P;
out normal<world> N;

void main() {
    P = worldFromObject * position;
    N = normalize(worldFromObject * objectNormal);
    gl_Position = clipFromWorld * P;
    // GL keeps the side where this is positive: only its sign matters, so the
    // length is handed over as a plain number of metres.
    gl_ClipDistance[0] = dot(clipNormal, P - clipPoint) / meter;
}
