#version 330 core
// Hand-written twin of shadow_map.sgl.frag.

uniform mat4      lightFromWorld;
uniform mat4      clipFromLight;
uniform sampler2D shadowMap;
uniform float     bias;
uniform vec3      Lshade;

in vec3 P;

out vec4 fragColor;

void main() {
    vec3 Pl = (lightFromWorld * vec4(P, 1.0)).xyz;
    vec4 h = clipFromLight * vec4(Pl, 1.0);
    vec3 ndc = h.xyz / h.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    float stored = texture(shadowMap, uv).r;
    float dist = length(Pl - vec3(0.0));
    float visible = dist - bias > stored ? 0.0 : 1.0;
    fragColor = vec4(Lshade * visible, 1.0);
}
