#version 460
// safegi-render-gpu's kernel: one sample of every pixel per dispatch, added
// to the film; the host divides by the sample count.
#include "integrator.sgl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= frame.imageWidth || pixel.y >= frame.imageHeight) return;
    uint index = pixel.y * frame.imageWidth + pixel.x;
    uint random = seedGenerator(index, pass.sampleIndex, pass.seed);
    // A box filter's sample: uniform over the pixel's area, the pixel's samples
    // spread evenly over it (Roberts' R2 sequence, a 2-D additive recurrence
    // of low discrepancy, shifted by a random offset fixed per pixel; each
    // sample alone is still uniform). Independent positions left a 5 cm
    // emitter's share of a pixel so noisy that many-lights.json's mean varied
    // by ±5 % between seeds at 128 spp.
    uint pixelRandom = seedGenerator(index, 0xffffffffu, pass.seed);
    vec2<1> shift = nextUniform2(pixelRandom);
    vec2<1> imagePoint = vec2<1>(vec2(pixel)) + fract(shift + float(pass.sampleIndex) * vec2(0.754877666246693, 0.569840290998053));
    uint rays = 0u;
    vec2<1> uLens = nextUniform2(random);
    spectrum<radiance> radiance = tracePath(cameraRay(imagePoint, uLens), random, rays);
    radianceSum[index] += radiance;
    rayCount[index] += rays;
}
