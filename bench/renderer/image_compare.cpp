// safegi-image-compare: relative RMSE and channel means of an image against a
// reference. relative_rmse = sqrt(mean over pixels and channels of
// (v - r)^2 / (r^2 + 0.01)); global_relative_rmse = sqrt(sum (v - r)^2 / sum r^2),
// which the bright light pixels dominate. The reference can be box-downsampled optionally after box-downsampling the reference to the image's
// size (a plain average, like a box filter over the larger pixels).
//   safegi-image-compare IMAGE REFERENCE
#include <cmath>
#include <cstdio>
#include <exception>

#include "safegi/cpu_renderer/image_io.hpp"

int main(int argc, char** argv) {
  using namespace safegi::render;
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s IMAGE REFERENCE\n", argv[0]);
    return 2;
  }
  try {
    Image image = read_image(argv[1]);
    Image reference = read_image(argv[2]);
    if (reference.width % image.width != 0 || reference.height % image.height != 0 ||
        reference.width / image.width != reference.height / image.height) {
      std::fprintf(stderr, "error: reference size must be an integer multiple of the image size\n");
      return 1;
    }
    int factor = reference.width / image.width;
    // Per-pixel relative error, regularised so that black pixels do not dominate.
    constexpr double kEpsilon = 1e-2;
    double error = 0, norm = 0, relative_mse = 0, sums[3] = {0, 0, 0}, reference_sums[3] = {0, 0, 0};
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) {
          double r = 0;
          for (int j = 0; j < factor; ++j)
            for (int i = 0; i < factor; ++i) r += reference.pixel(x * factor + i, y * factor + j)[c];
          r /= factor * factor;
          double v = image.pixel(x, y)[c];
          error += (v - r) * (v - r);
          relative_mse += (v - r) * (v - r) / (r * r + kEpsilon);
          norm += r * r;
          sums[c] += v;
          reference_sums[c] += r;
        }
    double samples = 3.0 * image.width * image.height;
    std::printf("{\"relative_rmse\": %.6f, \"global_relative_rmse\": %.6f, \"mean_ratio\": [%.5f, %.5f, %.5f], "
                "\"downsample\": %d}\n",
                std::sqrt(relative_mse / samples), std::sqrt(error / norm), sums[0] / reference_sums[0], sums[1] / reference_sums[1],
                sums[2] / reference_sums[2], factor);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
