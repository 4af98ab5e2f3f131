#version 330 core
#include <safegi/prelude.sgl>
// An assignment to a member of an instance-named block names the member,
// with its index or swizzle.
space tangent;
space world;
uniform point<tangent> viewPosTangent;
uniform point<world> viewPosWorld;
uniform vector<world> offsetWorld;
out VS_OUT {
    point<tangent> TangentViewPos;
    vector<tangent> Offsets[2];
} vs_out;
void main() {
    vs_out.TangentViewPos = viewPosWorld;
    vs_out.Offsets[1] = offsetWorld;
    vs_out.TangentViewPos.x = 2.0 * second;
    gl_Position = vec4(0.0);
}
