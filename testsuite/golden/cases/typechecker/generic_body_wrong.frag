#version 330 core
#include <safegi/prelude.sgl>
template<dimension D>
float<D> bad(float<D> a) { return a * a; }
void main() {}
