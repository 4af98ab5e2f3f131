#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<power> Phi;
out vec4 c;
void main() {
  // A point light of power Phi: its intensity is Phi / (4π sr). A literal kπ is a
  // π constant (docs/language.md, "Gradual typing"): 4π here is the sphere's
  // steradians. Normalised by π alone, no quantity π measures makes it an intensity.
  spectrum<intensity> I = Phi / (4.0 * 3.14159265);
  spectrum<intensity> improper = Phi / 3.14159265;
  c = vec4(I + improper, 1.0);
}
