#version 450
#include <safegi/prelude.sgl>
// Temporal reprojection of an SVGF denoiser in a GPU path tracer (CUDA
// kernels, rewritten as GLSL): the world position seen in this pixel is
// projected with the previous frame's world-to-clip matrix, itself the
// previous view-to-clip matrix applied after the previous world-to-view one,
// to find where it was on screen and fetch last frame's accumulated colour.
space world;
space view;
space clip;

uniform rigidmap<world, view> mtx_W2V;            // previous frame's camera
uniform projmap<view, clip> mtx_V2C;
uniform sampler2D prevColor;

in point<world> worldPos;
out vec4 fragColor;

projmap<world, clip> GetW2C()
{
    return mtx_W2V * mtx_V2C;
}

void main() {
    hpoint<clip> prevClip = GetW2C() * vec4(worldPos, 1.0);
    vec2 prevUv = prevClip.xy / prevClip.w * 0.5 + 0.5;
    if (any(lessThan(prevUv, vec2(0.0))) || any(greaterThan(prevUv, vec2(1.0)))) {
        discard;
    }
    fragColor = texture(prevColor, prevUv);
}
