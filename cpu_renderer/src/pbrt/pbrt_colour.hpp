// pbrt-v3's colours as its RGB build renders them. "xyz" through XYZToRGB;
// sampled spectra (wavelength, value pairs; pbrt-v4's named spectra of metals)
// and "blackbody" spectra: Planck's law
// normalised to 1 at its peak wavelength (pbrt-v3's BlackbodyNormalized), both
// integrated against the CIE 1931 colour-matching functions over 360-830 nm,
// scaled as RGBSpectrum::FromSampled scales, and converted with pbrt-v3's
// XYZToRGB.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace safegi::render::pbrt {

// pbrt-v3's XYZToRGB (sRGB primaries, D65).
std::array<double, 3> xyz_to_rgb(const std::array<double, 3>& xyz);
// CIE XYZ of the normalised blackbody at `kelvin` (> 0).
std::array<double, 3> normalized_blackbody_xyz(double kelvin);
// Linear sRGB (pbrt-v3's primaries) of the same.
std::array<double, 3> normalized_blackbody_rgb(double kelvin);

struct SpectrumSample {
  double wavelength_nm, value;
};
// pbrt-v3's RGBSpectrum::FromSampled: the spectrum through `samples` (any
// order, distinct wavelengths, at least one), linear between them and
// constant beyond its ends.
std::array<double, 3> sampled_spectrum_rgb(std::vector<SpectrumSample> samples);

// The named spectra of metals pbrt-v4 defines ("metal-Cu-eta", "metal-Cu-k",
// ... for Ag, Al, Au, Cu, CuZn: η and k of the complex index of
// refraction), converted as sampled_spectrum_rgb converts; nothing for other names.
std::optional<std::array<double, 3>> named_spectrum_rgb(std::string_view name);
bool is_named_spectrum(std::string_view name);
// Their names, quoted and comma-separated, for messages.
std::string named_spectrum_names();

}  // namespace safegi::render::pbrt
