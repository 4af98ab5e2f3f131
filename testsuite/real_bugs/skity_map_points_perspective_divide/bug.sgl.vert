#version 330 core
#include <safegi/prelude.sgl>
// A 2D vector-graphics library maps path points through a matrix that may
// carry perspective (a projective transform of the canvas); each mapped point
// is divided by its w before it is used as a device coordinate.
space local;
space device;

uniform projmap<local, device> matrix;

in point<local> srcPoint;
out point<device> dstPoint;

void main() {
    vec4 h = matrix * vec4(srcPoint, 1.0);
    dstPoint = h.xyz;
    gl_Position = vec4(0.0);
}
