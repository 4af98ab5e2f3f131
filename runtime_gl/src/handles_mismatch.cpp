// Must NOT compile (ctest runtime_gl.generated_handles_reject_a_wrong_dimension):
// irradiance given to the generated handle of a radiance uniform.
#include "emission_handles.hpp"

void set_emission(const safegi::gl::Program& program, const shaders::emission::Handles& handles) {
  program.set(handles.Le, safegi::spectrum<safegi::dim::irradiance>{});
}
