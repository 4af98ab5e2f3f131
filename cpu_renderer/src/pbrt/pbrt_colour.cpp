#include "pbrt/pbrt_colour.hpp"

#include <algorithm>
#include <cmath>

namespace safegi::render::pbrt {
namespace {

// Planck's law, W·sr⁻¹·m⁻³, with pbrt-v3's constants.
double planck(double wavelength_nm, double kelvin) {
  constexpr double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  double l = wavelength_nm * 1e-9;
  return 2 * h * c * c / (std::pow(l, 5) * (std::exp(h * c / (l * kb * kelvin)) - 1));
}

// One lobe of Wyman, Sloan and Shirley's fit of the CIE 1931 functions
// (JCGT 2(2), 2013): a Gaussian with a different width on each side. The fit
// stands in for the 471-entry table pbrt-v3 carries; chromaticities within
// 1.5e-3 of the Planckian locus from 2700 K up, 4e-3 at 2000 K (its red tail
// errs most; pbrt_import_features_test.cpp).
double lobe(double l, double mean, double width_below, double width_above) {
  double t = (l - mean) / (l < mean ? width_below : width_above);
  return std::exp(-0.5 * t * t);
}

std::array<double, 3> colour_matching(double l) {
  return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2),
          0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
          1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

// CIE XYZ of a spectrum given as a function of the wavelength in nm, as
// pbrt-v3's RGBSpectrum::FromSampled sums it: over its CIE range at its 1 nm
// samples, scaled so that a constant 1 has Y = 1.
template <class Spectrum>
std::array<double, 3> spectrum_xyz(const Spectrum& value_at_nm) {
  constexpr int first_nm = 360, samples = 471;
  constexpr double cie_y_integral = 106.856895;
  std::array<double, 3> xyz{0, 0, 0};
  for (int i = 0; i < samples; ++i) {
    double l = first_nm + i, value = value_at_nm(l);
    std::array<double, 3> cmf = colour_matching(l);
    for (int k = 0; k < 3; ++k) xyz[k] += value * cmf[k];
  }
  const double scale = double(samples - 1) / (cie_y_integral * samples);
  for (double& v : xyz) v *= scale;
  return xyz;
}

}  // namespace

std::array<double, 3> normalized_blackbody_xyz(double kelvin) {
  constexpr double wien_displacement = 2.8977721e-3;  // m·K
  const double peak = planck(wien_displacement / kelvin * 1e9, kelvin);
  return spectrum_xyz([&](double l) { return planck(l, kelvin) / peak; });
}

std::array<double, 3> sampled_spectrum_rgb(std::vector<SpectrumSample> samples) {
  std::sort(samples.begin(), samples.end(),
            [](const SpectrumSample& a, const SpectrumSample& b) { return a.wavelength_nm < b.wavelength_nm; });
  // pbrt-v3's InterpolateSpectrumSamples: linear between samples, the end values beyond them.
  auto value_at = [&](double l) {
    if (l <= samples.front().wavelength_nm) return samples.front().value;
    if (l >= samples.back().wavelength_nm) return samples.back().value;
    auto above = std::upper_bound(samples.begin(), samples.end(), l,
                                  [](double nm, const SpectrumSample& s) { return nm < s.wavelength_nm; });
    const SpectrumSample &a = above[-1], &b = above[0];
    double t = (l - a.wavelength_nm) / (b.wavelength_nm - a.wavelength_nm);
    return (1 - t) * a.value + t * b.value;
  };
  return xyz_to_rgb(spectrum_xyz(value_at));
}

std::array<double, 3> xyz_to_rgb(const std::array<double, 3>& v) {
  return {3.240479 * v[0] - 1.537150 * v[1] - 0.498535 * v[2], -0.969256 * v[0] + 1.875991 * v[1] + 0.041556 * v[2],
          0.055648 * v[0] - 0.204043 * v[1] + 1.057311 * v[2]};
}

std::array<double, 3> normalized_blackbody_rgb(double kelvin) { return xyz_to_rgb(normalized_blackbody_xyz(kelvin)); }

}  // namespace safegi::render::pbrt
