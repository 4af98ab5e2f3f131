// Handing a light the direction its light travels (light to lens) where it takes the
// direction from the lens to the light: the sign bug behind a black camera-facing light.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/orientation.hpp>

using namespace safegi;

namespace cf {
/// The light's facing factor toward the lens; lens_to_light points from the lens (the
/// shaded point) to the light.
float facing(oriented<away, direction<spaces::world>> lens_to_light, normal<spaces::world> light_normal) {
  return -raw(dot(light_normal, lens_to_light));
}

float seen_from(point<spaces::world> lens_position, point<spaces::world> light_position, normal<spaces::world> n) {
  const shaded_point<spaces::world> lens = shaded(lens_position);
#ifndef FIXED
  const auto light_to_lens = normalize(lens - light_position);
  return facing(light_to_lens, n);
#else
  const auto lens_to_light = normalize(light_position - lens);
  return facing(lens_to_light, n);
#endif
}
}  // namespace cf

int main() { return 0; }
