#version 330 core
#include <safegi/prelude.sgl>
// Generic helpers instantiated at each call.
space world;
space object;

uniform float<length> near;
uniform float<length> far;
uniform float<time> exposureTime;
uniform float<1> t;
uniform float<1> visibility;
uniform spectrum<radiance> Le;
uniform point<world> lightPos;
uniform point<object> lightPosObject;

in point<world> P;
out vec4 fragColor;

template<dimension D>
float<D> lerp(float<D> a, float<D> b, float<1> x) { return a + (b - a) * x; }

template<dimension D>
spectrum<D> attenuate(spectrum<D> x, float<1> v) { return x * v; }

template<space S>
float<length> separation(point<S> a, point<S> b) { return length(a - b); }

void main() {
    float<length> d = lerp(far, near, t);
    spectrum<radiance> L = attenuate(Le, visibility);
    float<length> gap = separation(P, lightPos);
    fragColor = vec4(L * (d / gap), 1.0);
}
