#version 450
// Issue 46, class 7: a vertex shader writes gl_Layer and gl_ViewportIndex with
// GL_ARB_shader_viewport_layer_array (or GL_NV_viewport_array2).
#extension GL_ARB_shader_viewport_layer_array : require
layout(location = 0) in vec4 position;
layout(location = 1) in int layer;
void main() {
    gl_Position = position;
    gl_Layer = layer;
    gl_ViewportIndex = layer / 2;
}
