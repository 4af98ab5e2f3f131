// gl_VertexIndex exists only in Vulkan GLSL (-V); OpenGL numbers vertices by gl_VertexID.
#version 450
void main() {
    gl_Position = vec4(float(gl_VertexIndex));
}
