#version 300 es
#include <safegi/prelude.sgl>
// WebGL engine's deferred renderer, ambient light pass: a uniform ambient light
// of radiance L reflected by a Lambertian surface of albedo rho leaves with
// radiance rho * L (the cosine-weighted hemisphere integral of rho / pi cancels
// the pi). Albedo comes from the G-buffer; empty pixels are skipped.
precision highp float;

uniform sampler2D gBufferTexture1;           // normal and glossiness
uniform sampler2D gBufferTexture3;           // albedo and metalness
uniform spectrum<radiance> lightColor;       // radiance of the uniform ambient light

in vec2 v_Texcoord;
out vec4 fragColor;

void main() {
    vec4 texel1 = texture(gBufferTexture1, v_Texcoord);
    if (dot(texel1.rgb, vec3(1.0)) == 0.0) {
        discard;
    }
    vec3 albedo = texture(gBufferTexture3, v_Texcoord).rgb;
    spectrum<radiance> L = lightColor * albedo;
    fragColor = vec4(L, 1.0);
}
