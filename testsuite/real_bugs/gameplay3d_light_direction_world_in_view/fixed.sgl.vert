#version 120
#include <safegi/prelude.sgl>
// A 3D game framework's built-in lit shader does its lighting in view space
// (the normal goes through the inverse transpose of the world-view matrix),
// so the scene's directional light, given in world space, is carried into
// view space by the view matrix before the Lambert cosine.
space object;
space world;
space view;
space clip;

uniform mat3<object, view, normal> u_inverseTransposeWorldViewMatrix;
uniform rigidmap<world, view> u_viewMatrix;
uniform projmap<object, clip> u_worldViewProjectionMatrix;
uniform direction<world, toward> u_directionalLightDirection;   // the way the light travels
uniform spectrum<irradiance / proj> u_directionalLightColor;
uniform spectrum<1> u_diffuseColor;

attribute point<object> a_position;
attribute normal<object> a_normal;
varying spectrum<radiance> v_color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 normalVector = normalize(u_inverseTransposeWorldViewMatrix * a_normal);
    vec3 lightDirection = (u_viewMatrix * vec4(u_directionalLightDirection, 0.0)).xyz;
    float ddot = max(dot(normalVector, -lightDirection), 0.0);
    v_color = u_diffuseColor * INV_PI * u_directionalLightColor * ddot;
    gl_Position = u_worldViewProjectionMatrix * vec4(a_position, 1.0);
}
