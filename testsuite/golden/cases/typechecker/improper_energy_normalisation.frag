#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<power> Phi;
out vec4 c;
void main() {
  // a point light of power Phi: intensity is Phi / (4 pi sr)
  spectrum<intensity> I = Phi / (4.0 * 3.14159265);
  c = vec4(I, 1.0);
}
