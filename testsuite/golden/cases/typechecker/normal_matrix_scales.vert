#version 330 core
#include <safegi/prelude.sgl>
// A normal matrix carries a normal's direction, not its length, when the
// model is scaled: normalize before a cosine. Written to an output it is
// fine (the fragment shader normalizes what it interpolates), and a rigid
// map keeps the length.
space object;
space view;
uniform mat3<object, view, normal> normalMatrix;
uniform mat3<object, view, rigid> rotation;
uniform direction<view, away> toLight;
in normal<object> aNormal;
out normal<view> vNormal;
out float lambert;
void main() {
    vNormal = normalMatrix * aNormal;
    float rigidCosine = max(dot(rotation * aNormal, toLight), 0.0);
    float good = max(dot(normalize(normalMatrix * aNormal), toLight), 0.0);
    float scaled = max(dot(normalMatrix * aNormal, toLight), 0.0);
    lambert = rigidCosine + good + scaled;
    gl_Position = vec4(0.0);
}
