#version 150 core
// The fixed-function state left the core profile in GLSL 1.40.
in vec4 position;
void main() {
  gl_Position = gl_ModelViewProjectionMatrix * position;
}
