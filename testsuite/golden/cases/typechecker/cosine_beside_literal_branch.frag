#version 330 core
#include <safegi/prelude.sgl>
// A literal branch of ?: beside a cosine is a cosine (a point light's is 1, the
// cosine of 0), as a literal bound of max is; beside a length it is still a
// plain number.
space world;
uniform normal<world> n;
uniform direction<world> l;
uniform float<length> d;
uniform bool pointLight;
out vec4 c;
void main() {
    float<proj> a = pointLight ? 1.0 : max(dot(n, l), 0.0);
    float<proj> b = pointLight ? max(dot(n, l), 0.0) : 1.0;
    float<length> wrong = pointLight ? 1.0 : d;
    c = vec4(a, b, wrong, 1.0);
}
