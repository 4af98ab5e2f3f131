// Calls offset() in whichever mode this file is compiled in.
#include "offset.hpp"

int main() {
  const auto p = offset(safegi::point<safegi::spaces::world>{});
  return safegi::raw(p).x == 1.0f ? 0 : 1;
}
