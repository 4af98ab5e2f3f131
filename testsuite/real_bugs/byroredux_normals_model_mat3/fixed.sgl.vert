#version 450
#include <safegi/prelude.sgl>
// A Vulkan renderer's mesh vertex shader: the model matrix arrives as a push
// constant and may scale non-uniformly (game meshes do), so normals go
// through the inverse transpose of its linear part, positions through the
// matrix itself.
space object;
space world;
space clip;

layout(push_constant) uniform PushConstants {
    map<object, world> model;
    projmap<world, clip> viewProj;
} pc;

layout(location = 0) in point<object> inPosition;
layout(location = 1) in normal<object> inNormal;
layout(location = 0) out point<world> fragWorldPos;
layout(location = 1) out normal<world> fragNormal;

void main() {
    vec4 worldPos = pc.model * vec4(inPosition, 1.0);
    fragWorldPos = worldPos.xyz;
    fragNormal = normalize(transpose(inverse(mat3(pc.model))) * inNormal);
    gl_Position = pc.viewProj * worldPos;
}
