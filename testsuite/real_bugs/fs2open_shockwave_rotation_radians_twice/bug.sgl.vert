#version 330 core
#include <safegi/prelude.sgl>
// A space game's 2D shockwaves: the rotation the table gives in degrees is
// converted to radians once, when the shockwave is created, and stored; the
// renderer spins the camera-facing quad's corners by that stored angle as it is.
space world;
space clip;

uniform projmap<world, clip> viewProj;
uniform point<world> center;
uniform direction<world> camRight;
uniform direction<world> camUp;
uniform float<length> radius;
uniform float<angle> rotation;       // radians, converted when the shockwave was created

in vec2 corner;                      // -1 .. 1
out vec2 uv;

void main() {
    float c = cos(radians(rotation));
    float s = sin(radians(rotation));
    vec2 r = vec2(c * corner.x - s * corner.y, s * corner.x + c * corner.y);
    point<world> p = center + (camRight * r.x + camUp * r.y) * radius;
    uv = corner * 0.5 + 0.5;
    gl_Position = viewProj * vec4(p, 1.0);
}
