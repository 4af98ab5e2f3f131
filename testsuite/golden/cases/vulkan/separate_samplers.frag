// RAW
// ARGS: -V -o /dev/null
// Separate images and samplers (GL_KHR_vulkan_glsl), combined at the lookup:
// every dimension, integer textures and shadow samplers. Issue 19, class 4.
#version 450
layout(set = 0, binding = 0) uniform texture2D albedo;
layout(set = 0, binding = 1) uniform textureCube sky;
layout(set = 0, binding = 2) uniform texture2DArray layers;
layout(set = 0, binding = 3) uniform utexture3D ids;
layout(set = 0, binding = 4) uniform texture2D shadowMap;
layout(set = 0, binding = 5) uniform sampler linearSampler;
layout(set = 0, binding = 6) uniform samplerShadow shadowSampler;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = texture(sampler2D(albedo, linearSampler), uv) + texture(samplerCube(sky, linearSampler), vec3(uv, 1.0)) +
            texture(sampler2DArray(layers, linearSampler), vec3(uv, 0.0)) +
            vec4(texture(usampler3D(ids, linearSampler), vec3(uv, 0.5)));
    color *= texture(sampler2DShadow(shadowMap, shadowSampler), vec3(uv, 0.5));
}
