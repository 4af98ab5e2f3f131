// Using a projected (homogeneous) point as a point.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
point<spaces::ndc> f(const projective_map<spaces::camera, spaces::ndc>& ndcFromCamera, point<spaces::camera> p) {
#ifndef FIXED
  point<spaces::ndc> q = ndcFromCamera(p);
  return q;
#else
  point<spaces::ndc> q = dehomogenize(ndcFromCamera(p));
  return q;
#endif
}
}  // namespace cf

int main() { return 0; }
