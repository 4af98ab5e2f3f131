#version 330 core
#include <safegi/prelude.sgl>
// Object -> world -> clip, with maps that say which spaces they connect.
space object;
space world;
space clip;

uniform map<object, world> worldFromObject;
uniform map<world, object> objectFromWorld;
uniform projmap<world, clip> clipFromWorld;
uniform point<world> lightInWorld;

in point<object> position;
out point<world> Pout;
out point<object> lightInObject;

void main() {
    point<world> P = worldFromObject * lightInWorld;
    lightInObject = objectFromWorld * lightInWorld;
    Pout = P;
    projmap<object, clip> clipFromObject = clipFromWorld * worldFromObject;
    hpoint<clip> h = clipFromObject * position;
    gl_Position = h;
}
