#version 330 core
// Hand-written twin of area_light.sgl.frag.

uniform vec3  lightCorner;
uniform vec3  lightEdgeU;
uniform vec3  lightEdgeV;
uniform vec3  lightNormal;
uniform vec3  Le;
uniform float lightArea;
uniform vec3  Kd;

in vec3 P;
in vec3 N;
in vec2 xi;

out vec4 fragColor;

void main() {
    vec3 Y = lightCorner + lightEdgeU * xi.x + lightEdgeV * xi.y;
    vec3 toLight = Y - P;
    float r2 = dot(toLight, toLight);
    vec3 wi = normalize(toLight);
    float cosX = max(dot(normalize(N), wi), 0.0);
    float cosY = max(-dot(normalize(lightNormal), wi), 0.0);
    float pdfA = 1.0 / lightArea;
    float pdfW = pdfA * r2 / (cosX * cosY);
    vec3 L = Kd * Le / pdfW;
    fragColor = vec4(L, 1.0);
}
