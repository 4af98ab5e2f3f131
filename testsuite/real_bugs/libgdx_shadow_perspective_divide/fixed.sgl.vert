#version 330 core
#include <safegi/prelude.sgl>
// A game framework's default vertex shader with a shadow map: the vertex in
// the light's clip space is divided by w before it becomes the shadow-map
// coordinate and depth, which a perspective (spot or point) light needs.
space object;
space world;
space clip;
space light_clip;

uniform map<object, world> u_worldTrans;
uniform projmap<world, clip> u_projViewTrans;
uniform projmap<world, light_clip> u_shadowMapProjViewTrans;

in point<object> a_position;
out vec3 v_shadowMapUv;

void main() {
    vec4 pos = u_worldTrans * vec4(a_position, 1.0);
    gl_Position = u_projViewTrans * pos;
    vec4 spos = u_shadowMapProjViewTrans * pos;
    v_shadowMapUv.xyz = (spos.xyz / spos.w) * 0.5 + 0.5;
}
