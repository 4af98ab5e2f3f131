#version 330 core
#include <safegi/prelude.sgl>
// Game's OpenGL per-pixel lighting, directional light: Lambert diffuse plus a
// Blinn-Phong highlight around the half vector between the light direction and
// the direction to the camera (the vertex stage passes camera - position).
space world;

uniform direction<world, away> uni_LightDirection;   // toward the light
uniform vec3 uni_LightDiffuse;
uniform vec3 uni_LightSpecular;
uniform vec3 uni_MaterialDiffuse;
uniform vec3 uni_MaterialSpecular;

in normal<world> pass_Normal;
in vector<world, away> pass_CameraDirection;
out vec4 out_FragColor;

void main() {
    vec3 normal = normalize(pass_Normal);
    vec3 lightDirection = uni_LightDirection;
    vec3 reflectDirection = -reflect(lightDirection, normal);
    float diffuseComponent = clamp(dot(normal, lightDirection), 0.0, 1.0);
    float specularComponent = clamp(pow(dot(normal, lightDirection + reflectDirection), 10.0), 0.0, 1.0);
    vec3 color = uni_MaterialDiffuse * uni_LightDiffuse * diffuseComponent
               + uni_MaterialSpecular * uni_LightSpecular * specularComponent;
    out_FragColor = vec4(color, 1.0);
}
