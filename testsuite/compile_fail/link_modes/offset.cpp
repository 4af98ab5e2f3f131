// Defines offset() in whichever mode this file is compiled in.
#include "offset.hpp"

safegi::point<safegi::spaces::world> offset(safegi::point<safegi::spaces::world> p) {
  return p + safegi::from_raw<safegi::vector<safegi::spaces::world>>(glm::vec3(1.0f, 0.0f, 0.0f));
}
