#version 330 core
#include <safegi/prelude.sgl>
// A tangent frame whose tangent and bitangent are plain vec3s (an unannotated
// attribute, cross(n, vec3(0.0, 0.0, 1.0))) is taken to be a frame of the space
// its annotated column is in: built around a view-space normal it maps into
// view, not into the world space its declaration names.
space world;
space view;
space tangent;
uniform sampler2D normalMap;
in normal<world> worldNormal;
in normal<view> viewNormal;
in vec2 uv;
out vec4 color;
void main() {
    vec3 n = normalize(worldNormal);
    vec3 t = normalize(cross(n, vec3(0.0, 0.0, 1.0)));
    mat3<tangent, world, rigid> tbn = mat3(t, cross(t, n), n);
    vec3 v = normalize(viewNormal);
    vec3 s = normalize(cross(v, vec3(0.0, 0.0, 1.0)));
    mat3<tangent, world, rigid> wrong = mat3(s, cross(s, v), v);
    vec3 nt = texture(normalMap, uv).xyz * 2.0 - 1.0;
    color = vec4(tbn * nt + wrong * nt, 1.0);
}
