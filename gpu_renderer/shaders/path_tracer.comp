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
    // A box filter's sample: uniform over the pixel's area.
    vec2<1> imagePoint = vec2<1>(vec2(pixel)) + nextUniform2(random);
    uint rays = 0u;
    vec2<1> uLens = nextUniform2(random);
    spectrum<radiance> radiance = tracePath(cameraRay(imagePoint, uLens), random, rays);
    radianceSum[index] += radiance;
    rayCount[index] += rays;
}
