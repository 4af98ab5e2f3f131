// A local of a helper function named like the per-vertex output `outColor[]`
// is the local: writing it is not a write of another invocation's vertex.
// Issue 19, false-positive class 7 (name resolution).
#version 450
layout(vertices = 3) out;
layout(location = 0) in vec3 inColor[];
layout(location = 0) out vec3 outColor[];
vec3 shade() {
    vec3 outColor;
    outColor = inColor[0] * 0.5;
    return outColor;
}
void main() {
    outColor[gl_InvocationID] = shade();
    gl_TessLevelInner[0] = 1.0;
    gl_TessLevelOuter[0] = 1.0;
    gl_TessLevelOuter[1] = 1.0;
    gl_TessLevelOuter[2] = 1.0;
}
