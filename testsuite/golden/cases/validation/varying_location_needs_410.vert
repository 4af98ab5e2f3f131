#version 330 core
// A layout(location) on an output between stages needs GLSL 4.10 (or GL_ARB_separate_shader_objects);
// at 3.30 only vertex inputs and fragment outputs take one.
layout(location = 0) in vec4 position;
layout(location = 1) out vec3 normal;
void main() {
  normal = vec3(0.0, 0.0, 1.0);
  gl_Position = position;
}
