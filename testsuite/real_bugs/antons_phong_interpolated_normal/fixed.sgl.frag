#version 410
#include <safegi/prelude.sgl>
// A tutorial book's per-fragment Phong shader in eye space: the interpolated
// eye-space normal is renormalised before the diffuse cosine and before the
// reflection of the light direction about it.
space eye : eye;

uniform point<eye> light_position_eye;
uniform vec3 Ls;
uniform vec3 Ld;
uniform vec3 La;
uniform vec3 Ks;
uniform vec3 Kd;
uniform vec3 Ka;
uniform float specular_exponent;

in point<eye, shaded> position_eye;
in normal<eye> normal_eye;
out vec4 fragment_colour;

void main() {
    vec3 n_eye = normalize(normal_eye);
    vec3 Ia = La * Ka;
    vec3 direction_to_light_eye = normalize(light_position_eye - position_eye);
    float dot_prod = max(dot(direction_to_light_eye, n_eye), 0.0);
    vec3 Id = Ld * Kd * dot_prod;
    vec3 reflection_eye = reflect(-direction_to_light_eye, n_eye);
    vec3 surface_to_viewer_eye = normalize(-position_eye);
    float dot_prod_specular = max(dot(reflection_eye, surface_to_viewer_eye), 0.0);
    float specular_factor = pow(dot_prod_specular, specular_exponent);
    vec3 Is = Ls * Ks * specular_factor;
    fragment_colour = vec4(Is + Id + Ia, 1.0);
}
