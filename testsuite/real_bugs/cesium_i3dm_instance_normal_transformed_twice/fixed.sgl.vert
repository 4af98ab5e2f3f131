#version 300 es
#include <safegi/prelude.sgl>
// A globe renderer's instanced 3D tiles: each instance's transform (instance
// -> tile model) is a per-instance attribute; the normal goes to eye space by
// the model's normal matrix composed with the normal matrix of the instance
// transform, once.
precision highp float;
space instance;
space model;
space eye : eye;
space clip;

uniform map<model, eye> czm_modelView;
uniform mat3<model, eye, normal> czm_normal;
uniform projmap<eye, clip> czm_projection;

in map<instance, model> a_instancingTransform;
in point<instance> a_positionMC;
in normal<instance> a_normalMC;
out normal<eye> v_normalEC;

void main() {
    mat3 instanceNormalMatrix = czm_normal * transpose(inverse(mat3(a_instancingTransform)));
    v_normalEC = normalize(instanceNormalMatrix * a_normalMC);
    vec4 positionEC = czm_modelView * (a_instancingTransform * vec4(a_positionMC, 1.0));
    gl_Position = czm_projection * positionEC;
}
