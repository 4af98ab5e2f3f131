#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
space clip;

uniform map<object, world> worldFromObject;
uniform projmap<world, clip> clipFromWorld;
in point<object> position;
in normal<object> objectNormal;
out normal<world> N;
out spectrum<radiance> Lv;

void main() {
    point<world> P = worldFromObject * position;
    N = normalize(worldFromObject * objectNormal);
    Lv = spectrum<radiance>(0.0);
    gl_Position = clipFromWorld * P;
}
