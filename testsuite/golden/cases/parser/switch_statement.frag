#version 330 core
flat in int mode;
out vec4 c;
void main() {
  switch (mode) {
    case 0: c = vec4(0.0); break;
    case 1:
    case 2: c = vec4(1.0); break;
    default: discard;
  }
}
