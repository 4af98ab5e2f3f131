#version 330 core
#include <safegi/prelude.sgl>
// A cosine kept off zero by a named plain constant bounds as the literal would:
// the bound takes the cosine's dimension. A named length is no such bound.
space world;
const float EPSILON = 1e-4;
const float<length> BIAS = 0.01 * meter;
uniform normal<world> n;
uniform direction<world> l;
out vec4 c;
void main() {
    float<proj> cosine = max(dot(n, l), EPSILON);
    float<proj> wrong = max(dot(n, l), BIAS);
    c = vec4(cosine, wrong, 0.0, 1.0);
}
