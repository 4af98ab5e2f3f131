// RAW
// ARGS: -V -o /dev/null
// GL_EXT_fragment_shader_barycentric: per-vertex inputs of a fragment shader.
// Issue 19, false-positive class 6.
#version 460
#extension GL_EXT_fragment_shader_barycentric : require
layout(location = 0) in pervertexEXT vec3 c[];
layout(location = 0) out vec4 color;
void main() {
    color = vec4(c[0] * gl_BaryCoordEXT.x + c[1] * gl_BaryCoordEXT.y + c[2] * gl_BaryCoordEXT.z, 1.0);
}
