#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(max_vertices = 4) out;
in vec4 color[];
out vec4 fragment_color;
void main() {
  for (int i = 0; i < 3; ++i) {
    fragment_color = color[i];
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
}
