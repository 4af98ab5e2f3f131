// Perlin's gradient noise and the sums built on it, as pbrt-v3 defines them
// (its core/texture.cpp), so that its procedural textures render as there.
//
// Noise works on plain numbers: the coordinates of a texture space whose unit
// is one noise cell; a procedural texture's mapping says what length that is.
// `footprint` is how far the point moves, in those units, between neighbouring
// camera rays (zero: no filtering, every octave); sums drop the octaves whose
// detail would be finer than it, as pbrt-v3's FBm and Turbulence do.
#pragma once

#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

struct NoisePoint {
  Real x = 0, y = 0, z = 0;
};

// Perlin's improved noise (2002) with pbrt-v3's gradients: 0 at every lattice
// point, smooth (C2), within about [-1, 1]; periodic with period 256. Not-finite
// coordinates give 0.
Real perlin_noise(NoisePoint p);
// pbrt-v3's 2D noise: the plane z = 0.5 of the 3D one.
Real perlin_noise(Real x, Real y);

// Fractional Brownian motion: octaves of noise, each at 1.99 times the
// frequency and `omega` times the amplitude of the last; at most `max_octaves`.
Real fbm(NoisePoint p, Real footprint, Real omega, int max_octaves);
// The same sum of |noise|; octaves dropped for the footprint count 0.2 each
// (pbrt-v3's estimate of their mean).
Real turbulence(NoisePoint p, Real footprint, Real omega, int max_octaves);

}  // namespace safegi::render
