#version 330 core
#include <safegi/prelude.sgl>
// Assigning to a member of an input block names the member and the read-only
// instance it belongs to.
space tangent;
in VS_OUT {
    point<tangent> TangentViewPos;
} fs_in;
out vec4 c;
void main() {
    fs_in.TangentViewPos = point<tangent>(vec3(0.0));
    c = vec4(1.0);
}
