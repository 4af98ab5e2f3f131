// RAW
// ARGS: -V -o /dev/null
// -V: Vulkan semantics, as glslangValidator -V, which says of the emitted GLSL:
//   ERROR: 0:8: 'non-opaque uniforms outside a block' : not allowed when using GLSL for Vulkan
// The message is glslang's, at the annotated line. -R (relaxed rules) accepts it.
#version 450
uniform vec4 c;
layout(location = 0) out vec4 color;
void main() {
    color = c;
}
