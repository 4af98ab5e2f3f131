#version 300 es
#include <safegi/prelude.sgl>
// A volume renderer draws the faces of a mesh's cells and integrates along
// the view ray through each cell. The cell vertices arrive in the mesh's own
// coordinates, so the world-space camera position is carried into them by
// the inverse of the model matrix before the ray direction is formed.
precision highp float;
space object;
space world;

uniform map<world, object> inverseModelMatrix;
uniform point<world> cameraPosition;
uniform float<inv_length> extinction;

in point<object> v_model_position;
in float<length> v_depth_through_cell;
out vec4 fragColor;

void main() {
    point<object> camera_object = (inverseModelMatrix * vec4(cameraPosition, 1.0)).xyz;
    vec3 ray = normalize(v_model_position - camera_object);
    float absorbed = 1.0 - exp(-extinction * v_depth_through_cell);
    fragColor = vec4(abs(ray) * absorbed, absorbed);
}
