#version 330 core
#include <safegi/prelude.sgl>
// A planetarium's lunar-Lambert surface: a blend of Lambert's law and the
// Lommel-Seeliger law mu0 / (mu0 + mu). The Lommel-Seeliger term needs a
// factor 2 so that, like Lambert's mu0, it is 1 where the sun and the eye are
// both overhead.
space world;

uniform direction<world, away> sunDir;        // toward the sun
uniform float<1> lunarLambert;               // 0: Lambert, 1: Lommel-Seeliger
uniform vec3 albedo;

in normal<world> vNormal;
in direction<world, away> vToEye;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    float mu0 = max(dot(n, sunDir), 0.0);
    float mu = max(dot(n, vToEye), 0.0);
    float lommelSeeliger = 2.0 * mu0 / (mu0 + mu + 1e-4);
    float brightness = mix(mu0, lommelSeeliger, lunarLambert);
    fragColor = vec4(albedo * brightness, 1.0);
}
