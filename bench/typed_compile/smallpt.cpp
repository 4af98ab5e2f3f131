// smallpt (Kevin Beason's 99-line path tracer) ported to the typed library, as a
// newcomer would port it: the compile-time benchmark's user program
// (bench/typed_compile/run.py compiles it checked and with -DSAFEGI_UNCHECKED=1).
// It also runs: ./smallpt [samples per pixel] writes image.ppm.
#include <safegi/typed.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sg = safegi;
using namespace safegi;
using spaces::world;

namespace {

using length = quantity<dim::length>;
using area = quantity<dim::area>;
using radiance = spectrum<dim::radiance>;
using albedo = spectrum<dim::dimensionless>;

/// A small deterministic generator in [0, 1) (smallpt uses erand48).
struct rng {
  unsigned long long state;
  float next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return float(state >> 40) / float(1ULL << 24);
  }
};

enum class material { diffuse, specular, refractive };

struct sphere {
  length radius;
  point<world> centre;
  radiance emission;
  albedo colour;
  material kind;

  /// The distance along r to the nearest hit, or zero on a miss.
  length intersect(const ray<world>& r) const {
    const vector<world> op = centre - r.o;
    const length eps = 1e-4f * units::metre;
    const length b = sg::dot(op, r.d);
    const area det = b * b - sg::dot(op, op) + radius * radius;
    if (det < sg::zero) return sg::zero;
    const length root = sg::sqrt(det);
    if (b - root > eps) return b - root;
    if (b + root > eps) return b + root;
    return sg::zero;
  }
};

point<world> at(float x, float y, float z) {
  return point<world>(x * units::metre, y * units::metre, z * units::metre);
}
radiance emitted(float r, float g, float b) {
  return radiance(r * units::radiance_unit, g * units::radiance_unit, b * units::radiance_unit);
}

const sphere spheres[] = {
    {1e5f * units::metre, at(1e5f + 1, 40.8f, 81.6f), radiance{}, albedo(.75f, .25f, .25f), material::diffuse},
    {1e5f * units::metre, at(-1e5f + 99, 40.8f, 81.6f), radiance{}, albedo(.25f, .25f, .75f), material::diffuse},
    {1e5f * units::metre, at(50, 40.8f, 1e5f), radiance{}, albedo(.75f, .75f, .75f), material::diffuse},
    {1e5f * units::metre, at(50, 40.8f, -1e5f + 170), radiance{}, albedo(0, 0, 0), material::diffuse},
    {1e5f * units::metre, at(50, 1e5f, 81.6f), radiance{}, albedo(.75f, .75f, .75f), material::diffuse},
    {1e5f * units::metre, at(50, -1e5f + 81.6f, 81.6f), radiance{}, albedo(.75f, .75f, .75f), material::diffuse},
    {16.5f * units::metre, at(27, 16.5f, 47), radiance{}, albedo(.999f, .999f, .999f), material::specular},
    {16.5f * units::metre, at(73, 16.5f, 78), radiance{}, albedo(.999f, .999f, .999f), material::refractive},
    {600 * units::metre, at(50, 681.6f - .27f, 81.6f), emitted(12, 12, 12), albedo(0, 0, 0), material::diffuse},
};

bool intersect(const ray<world>& r, length& t, int& id) {
  t = std::numeric_limits<length>::infinity();
  for (int i = int(sizeof spheres / sizeof spheres[0]); i--;) {
    const length d = spheres[i].intersect(r);
    if (d > sg::zero && d < t) {
      t = d;
      id = i;
    }
  }
  return t < std::numeric_limits<length>::infinity();
}

float clamp01(float x) { return x < 0 ? 0 : x > 1 ? 1 : x; }
int to_byte(float x) { return int(std::pow(clamp01(x), 1 / 2.2f) * 255 + .5f); }

radiance trace(const ray<world>& r, int depth, rng& random) {
  length t;
  int id = 0;
  if (!intersect(r, t, id)) return radiance{};
  const sphere& obj = spheres[id];
  const point<world> x = r(t);
  const normal<world> n = sg::to_normal(sg::normalize(x - obj.centre));
  const normal<world> nl = sg::dot(n, r.d) < sg::zero ? n : -n;
  albedo f = obj.colour;
  const float p = std::fmax(std::fmax(f.r(), f.g()), f.b());
  if (++depth > 5) {
    if (random.next() < p)
      f = f * (1 / p);
    else
      return obj.emission;
  }
  if (depth > 100) return obj.emission;
  if (obj.kind == material::diffuse) {
    const float r1 = 2 * float(M_PI) * random.next(), r2 = random.next(), r2s = std::sqrt(r2);
    const frame<world> local = frame<world>::from_normal(nl);
    const direction<spaces::shading> d_local(std::cos(r1) * r2s, std::sin(r1) * r2s, std::sqrt(1 - r2));
    const direction<world> d = local.from_local(d_local);
    return obj.emission + f * trace(ray<world>(x, d), depth, random);
  }
  const direction<world> reflected = sg::reflect(r.d, n);
  if (obj.kind == material::specular) return obj.emission + f * trace(ray<world>(x, reflected), depth, random);
  const ray<world> reflection(x, reflected);
  const bool into = sg::dot(n, nl) > 0;
  const float nc = 1, nt = 1.5f, nnt = into ? nc / nt : nt / nc, ddn = sg::raw(sg::dot(r.d, nl));
  const float cos2t = 1 - nnt * nnt * (1 - ddn * ddn);
  if (cos2t < 0) return obj.emission + f * trace(reflection, depth, random);  // total internal reflection
  const vector<world, dim::dimensionless> refracted =
      r.d * nnt - sg::to_direction(n) * ((into ? 1 : -1) * (ddn * nnt + std::sqrt(cos2t)));
  const direction<world> tdir = sg::normalize(refracted);
  const float a = nt - nc, b = nt + nc, R0 = a * a / (b * b), c = 1 - (into ? -ddn : sg::raw(sg::dot(tdir, n)));
  const float Re = R0 + (1 - R0) * c * c * c * c * c, Tr = 1 - Re, P = .25f + .5f * Re, RP = Re / P,
              TP = Tr / (1 - P);
  radiance incoming;
  if (depth > 2)
    incoming = random.next() < P ? trace(reflection, depth, random) * RP
                                 : trace(ray<world>(x, tdir), depth, random) * TP;
  else
    incoming = trace(reflection, depth, random) * Re + trace(ray<world>(x, tdir), depth, random) * Tr;
  return obj.emission + f * incoming;
}

}  // namespace

int main(int argc, char* argv[]) {
  const int w = 256, h = 192, samps = argc == 2 ? std::atoi(argv[1]) / 4 : 1;
  const ray<world> cam(at(50, 52, 295.6f), sg::normalize(vector<world, dim::dimensionless>(0, -0.042612f, -1)));
  const vector<world, dim::dimensionless> cx(w * .5135f / h, 0, 0);
  const vector<world, dim::dimensionless> cy = sg::normalize(sg::cross(cx, cam.d)) * .5135f;
  static radiance image[w * h];
  for (int y = 0; y < h; y++) {
    rng random{static_cast<unsigned long long>(y) * y * y};
    for (unsigned short x = 0; x < w; x++) {
      for (int sy = 0, i = (h - y - 1) * w + x; sy < 2; sy++) {
        for (int sx = 0; sx < 2; sx++) {
          radiance sum;
          for (int s = 0; s < samps; s++) {
            const float r1 = 2 * random.next(), dx = r1 < 1 ? std::sqrt(r1) - 1 : 1 - std::sqrt(2 - r1);
            const float r2 = 2 * random.next(), dy = r2 < 1 ? std::sqrt(r2) - 1 : 1 - std::sqrt(2 - r2);
            const vector<world, dim::dimensionless> d = cx * (((sx + .5f + dx) / 2 + x) / w - .5f) +
                                                        cy * (((sy + .5f + dy) / 2 + y) / h - .5f) + cam.d;
            const direction<world> dir = sg::normalize(d);
            sum = sum + trace(ray<world>(cam.o + dir * (140 * units::metre), dir), 0, random) * (1.f / samps);
          }
          image[i] = image[i] + sum * .25f;
        }
      }
    }
  }
  std::FILE* out = std::fopen("image.ppm", "w");
  if (!out) return 1;
  std::fprintf(out, "P3\n%d %d\n%d\n", w, h, 255);
  for (const radiance& c : image) {
    std::fprintf(out, "%d %d %d ", to_byte(sg::in(c.r(), units::radiance_unit)), to_byte(sg::in(c.g(), units::radiance_unit)),
                 to_byte(sg::in(c.b(), units::radiance_unit)));
  }
  std::fclose(out);
  return 0;
}
