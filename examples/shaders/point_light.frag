#version 330 core
// Hand-written twin of point_light.sgl.frag.

uniform vec3 lightPos;
uniform vec3 lightI;
uniform vec3 Kd;

in vec3 P;
in vec3 N;

out vec4 fragColor;

void main() {
    vec3 toLight = lightPos - P;
    float d = length(toLight);
    vec3 wi = normalize(toLight);
    float cosTheta = max(dot(normalize(N), wi), 0.0);
    float G = 1.0 / (d * d);
    vec3 L = Kd * lightI * cosTheta * G;
    fragColor = vec4(L, 1.0);
}
