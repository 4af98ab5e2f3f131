#version 450
#include <safegi/prelude.sgl>
// A graphics API's shadow example: the fragment's position in each light's
// clip space is divided by w and mapped to texture coordinates, with y
// flipped (texture v grows downwards, clip y upwards), and compared with the
// stored depth by the hardware.
space world;
space light_clip;

layout(set = 0, binding = 1) uniform Lights {
    projmap<world, light_clip> lightProj[4];
};
layout(set = 0, binding = 2) uniform sampler2DArrayShadow t_Shadow;

layout(location = 0) in point<world> v_Position;
layout(location = 0) out vec4 o_Target;

float fetch_shadow(int light_id, hpoint<light_clip> homogeneous_coords) {
    if (homogeneous_coords.w <= 0.0) {
        return 1.0;
    }
    vec4 light_local = vec4((homogeneous_coords.xy / homogeneous_coords.w + 1.0) / 2.0,
                            float(light_id), homogeneous_coords.z / homogeneous_coords.w);
    return texture(t_Shadow, light_local);
}

void main() {
    float shadow = 1.0;
    for (int i = 0; i < 4; ++i) {
        shadow *= fetch_shadow(i, lightProj[i] * vec4(v_Position, 1.0));
    }
    o_Target = vec4(vec3(shadow), 1.0);
}
