// pbrt-v3's colours as its RGB build renders them. "xyz" through XYZToRGB;
// "blackbody" spectra: Planck's law
// normalised to 1 at its peak wavelength (pbrt-v3's BlackbodyNormalized), then
// integrated against the CIE 1931 colour-matching functions over 360-830 nm,
// scaled as RGBSpectrum::FromSampled scales, and converted with pbrt-v3's
// XYZToRGB.
#pragma once

#include <array>

namespace safegi::render::pbrt {

// pbrt-v3's XYZToRGB (sRGB primaries, D65).
std::array<double, 3> xyz_to_rgb(const std::array<double, 3>& xyz);
// CIE XYZ of the normalised blackbody at `kelvin` (> 0).
std::array<double, 3> normalized_blackbody_xyz(double kelvin);
// Linear sRGB (pbrt-v3's primaries) of the same.
std::array<double, 3> normalized_blackbody_rgb(double kelvin);

}  // namespace safegi::render::pbrt
