// Float against double in the typed library, on a kernel: the irradiance at a
// point from a rectangular lambertian emitter (a 0.5 m square, 0.2 m above the receiver at one corner),
// estimated by Monte Carlo over the emitter's area,
//   E = (1/N) sum Le cos(theta_x) cos(theta_y) / r^2 * A,
// against its closed form. The CPU renderer cannot switch precision (its
// spectra are float-only, and it already sums pixels in double), so the trade
// is measured here with the same typed code instantiated for
// quantity<D, float> and quantity<D, double>, and with a float or a double
// accumulator.
//   safegi_precision_bench [max_log10_samples=8] [seeds=4]
// Prints one JSON line per (variant, N): CPU seconds and relative error (RMS over seeds).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numbers>

#include <safegi/typed/quantity.hpp>

namespace {

using namespace safegi;
using area_dim = dim::pow<dim::length, 2>;
// Radiance per unit of the result: the light's Le is 1 W/(m² sr); irradiance in W/m².
using radiance_dim = dim::quotient<dim::quotient<dim::quotient<dim::power, area_dim>, dim::solid_angle>, dim::proj>;
using irradiance_dim = dim::quotient<dim::power, area_dim>;

// PCG32 (O'Neill): the same integer stream for every variant.
struct Pcg32 {
  std::uint64_t state;
  std::uint32_t next() {
    std::uint64_t old = state;
    state = old * 6364136223846793005ULL + 1442695040888963407ULL;
    auto shifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (shifted >> rot) | (shifted << ((-rot) & 31u));
  }
  template <class T>
  T uniform() {
    return static_cast<T>(next() >> 8) * static_cast<T>(1.0 / 16777216.0);  // 24 bits: exact in float
  }
};

// Closed form: point at height c below one corner of an a×b emitter facing it
// (the emitter's normal pointing at the receiver's plane), both parallel.
double exact_irradiance(double a, double b, double c) {
  double x = a / c, y = b / c;
  double form_factor = 1.0 / (2.0 * std::numbers::pi) *
                       (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                        y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
  return std::numbers::pi * form_factor;  // Le = 1
}

template <class T, class Accumulator>
double estimate(std::uint64_t samples, std::uint64_t seed, double a_, double b_, double c_) {
  using Length = quantity<dim::length, T>;
  using Radiance = quantity<radiance_dim, T>;
  using Irradiance = quantity<irradiance_dim, T>;
  const Length a = from_raw<Length>(static_cast<T>(a_)), b = from_raw<Length>(static_cast<T>(b_)),
               c = from_raw<Length>(static_cast<T>(c_));
  const Radiance le = from_raw<Radiance>(T(1));
  const auto area = a * b;
  Pcg32 rng{seed * 0x9E3779B97F4A7C15ULL + 1};
  Accumulator sum = 0;
  for (std::uint64_t i = 0; i < samples; ++i) {
    Length x = a * rng.uniform<T>(), y = b * rng.uniform<T>();
    auto r2 = x * x + y * y + c * c;
    // cos θ at both ends is c / r: the two cosines (proj and solid-angle measure) times area / r².
    quantity<dim::proj, T> cos_receiver = from_raw<quantity<dim::proj, T>>(raw(c / sqrt(r2)));
    auto cos_emitter = raw(c / sqrt(r2));
    auto solid_angle = from_raw<quantity<dim::solid_angle, T>>(cos_emitter * raw(area / r2));
    Irradiance e = le * cos_receiver * solid_angle;
    sum += static_cast<Accumulator>(raw(e));
  }
  return static_cast<double>(sum) / static_cast<double>(samples);
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

template <class T, class Accumulator>
void run(const char* name, int max_log10, int seeds) {
  const double a = 0.5, b = 0.5, c = 0.2;  // metres: a large emitter close to the receiver (a varied integrand)
  const double exact = exact_irradiance(a, b, c);
  for (int k = 1; k <= max_log10; ++k) {
    auto samples = static_cast<std::uint64_t>(std::pow(10.0, k));
    double squared = 0, start = cpu_seconds();
    for (int s = 0; s < seeds; ++s) {
      double e = estimate<T, Accumulator>(samples, static_cast<std::uint64_t>(s), a, b, c);
      squared += (e - exact) * (e - exact) / (exact * exact);
    }
    double seconds = (cpu_seconds() - start) / seeds;
    std::printf("{\"variant\": \"%s\", \"samples\": %llu, \"cpu_seconds\": %.6f, \"relative_error\": %.3e}\n", name,
                static_cast<unsigned long long>(samples), seconds, std::sqrt(squared / seeds));
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int max_log10 = argc > 1 ? std::atoi(argv[1]) : 8;
  int seeds = argc > 2 ? std::atoi(argv[2]) : 4;
  run<float, float>("float, float sum", max_log10, seeds);
  run<float, double>("float, double sum", max_log10, seeds);
  run<double, double>("double, double sum", max_log10, seeds);
  return 0;
}
