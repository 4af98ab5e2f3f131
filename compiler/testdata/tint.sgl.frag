#version 330 core
#include <safegi/prelude.sgl>
space world;

in normal<world> N;
in spectrum<radiance> Lv;
uniform spectrum<1> tint;
out vec4 color;

void main() {
    spectrum<radiance> L = Lv * tint;
    color = vec4(L, 1.0);
}
