#version 330 core
#include <safegi/prelude.sgl>
// An assignment to a member of an instance-named block names the member.
space tangent;
space world;
uniform point<tangent> viewPosTangent;
uniform point<world> viewPosWorld;
out VS_OUT {
    point<tangent> TangentViewPos;
} vs_out;
void main() {
    vs_out.TangentViewPos = viewPosWorld;
    gl_Position = vec4(0.0);
}
