#version 330 core
#include <safegi/prelude.sgl>
// A GLSL path tracer's closest hit with a normal map: the mesh's normal,
// tangent and bitangent are all carried from object to world space by the
// instance transform before the tangent-space normal is applied.
space object;
space world;

uniform map<object, world> transform;
uniform sampler2D normalMap;

in normal<object> hitNormal;
in vector<object> hitTangent;
in vector<object> hitBitangent;
in vec2 texUV;
out vec4 shadingNormalOut;

void main() {
    vec3 normal = normalize(transform * hitNormal);
    vector<object> tangent = hitTangent;
    vector<object> bitangent = hitBitangent;
    vec3 texNormal = normalize(texture(normalMap, texUV).rgb * 2.0 - 1.0);
    vector<world, 1> shading = tangent / length(tangent) * texNormal.x
                             + bitangent / length(bitangent) * texNormal.y + normal * texNormal.z;
    shadingNormalOut = vec4(normalize(shading), 0.0);
}
