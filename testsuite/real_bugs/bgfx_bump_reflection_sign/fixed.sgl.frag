#version 330 core
#include <safegi/prelude.sgl>
// A rendering library's normal-mapping example: each point light's direction
// is carried from world to tangent space by the transpose of the TBN frame,
// and a Phong lobe compares the mirror direction of the light about the
// mapped normal with the view direction. With the light direction pointing
// away from the surface, its mirror image is 2 (n.l) n - l.
space world;
space tangent;

uniform vec4 u_lightPosRadius[4];
uniform vec4 u_lightRgbInnerR[4];
uniform sampler2D s_texNormal;

in point<world, shaded> v_wpos;
in direction<tangent, away> v_view;
in direction<world> v_normal;
in direction<world> v_tangent;
in direction<world> v_bitangent;
in vec2 v_texcoord0;
out vec4 fragColor;

vec2 blinn(direction<tangent, away> _lightDir, normal<tangent> _normal, direction<tangent, away> _viewDir) {
    float ndotl = dot(_normal, _lightDir);
    vec3 reflected = 2.0 * ndotl * _normal - _lightDir;
    float rdotv = dot(reflected, _viewDir);
    return vec2(ndotl, rdotv);
}

vec3 calcLight(int _idx, mat3<tangent, world, rigid> _tbn, point<world, shaded> _wpos, normal<tangent> _normal, direction<tangent, away> _view) {
    point<world> lightPos = point<world>(u_lightPosRadius[_idx].xyz);
    vec3 lp = lightPos - _wpos;
    float attn = 1.0 - smoothstep(u_lightRgbInnerR[_idx].w, 1.0, length(lp) / u_lightPosRadius[_idx].w);
    vec3 lightDir = normalize(lp) * _tbn;
    vec2 bln = blinn(lightDir, _normal, _view);
    float diffuse = max(bln.x, 0.0);
    float specular = (bln.x > 0.0) ? pow(max(bln.y, 0.0), 16.0) : 0.0;
    return u_lightRgbInnerR[_idx].xyz * (diffuse + specular) * attn;
}

void main() {
    mat3<tangent, world, rigid> tbn = mat3(v_tangent, v_bitangent, v_normal);
    vec3 n;
    n.xy = texture(s_texNormal, v_texcoord0).xy * 2.0 - 1.0;
    n.z = sqrt(1.0 - dot(n.xy, n.xy));
    normal<tangent> nT = normal<tangent>(n);
    direction<tangent, away> view = normalize(v_view);
    vec3 lightColor = calcLight(0, tbn, v_wpos, nT, view) + calcLight(1, tbn, v_wpos, nT, view);
    fragColor = vec4(lightColor, 1.0);
}
