#version 120
// texture() is a GLSL 1.30 name; a 1.20 shader spells it texture2D().
uniform sampler2D albedo;
varying vec2 uv;
void main() {
  gl_FragColor = texture(albedo, uv);
}
