// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// A fragment shader's per-vertex input (GL_EXT_fragment_shader_barycentric,
// GL_NV_fragment_shader_barycentric) holds one value per vertex of the
// primitive: `pervertexEXT in float a[3]` takes one location, as a geometry
// shader's inputs do (glslang's spv.fragmentShaderBarycentric2.frag). An
// ordinary input array still takes one location an element.
#version 450
#extension GL_EXT_fragment_shader_barycentric : require
layout(location = 0) pervertexEXT in float a[3];
layout(location = 1) pervertexEXT in float b[3];
layout(location = 2) in float c[2];
layout(location = 3) in float d;
layout(location = 0) out vec4 color;
void main() {
  color = vec4(gl_BaryCoordEXT.x * a[0] + gl_BaryCoordEXT.y * b[1], c[0], d, 1.0);
}
