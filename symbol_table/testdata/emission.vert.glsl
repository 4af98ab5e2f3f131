#version 330 core
                             
                                     
// A triangle in normalized device coordinates carrying emitted radiance.
in vec3       position;
in vec3               vertexLe;
out vec3               Lv;
void main() {
  Lv = vertexLe;
  gl_Position = vec4(position, 1.0);
}
