#version 330 core
#include <safegi/prelude.sgl>
// A ray-tracing sample's pinhole camera: the screen's half-height at unit
// distance is tan(fovy / 2).
space world;

uniform float<angle> fovy;
uniform vec2 fbSize;
uniform point<world> from;
uniform point<world> at;
uniform direction<world> lookUp;
uniform samplerCube<spectrum<radiance>> env;

out vec4 fragColor;

void main() {
    float aspect = fbSize.x / fbSize.y;
    vec3 camera_d00 = normalize(at - from);
    float fovyScale = tan(fovy * 0.5);
    vec3 camera_ddu = fovyScale * aspect * normalize(cross(camera_d00, lookUp));
    vec3 camera_ddv = fovyScale * normalize(cross(camera_ddu, camera_d00));
    vec2 screen = (gl_FragCoord.xy / fbSize) * 2.0 - 1.0;
    direction<world> dir = normalize(camera_d00 + screen.x * camera_ddu + screen.y * camera_ddv);
    fragColor = vec4(texture(env, dir).rgb, 1.0);
}
