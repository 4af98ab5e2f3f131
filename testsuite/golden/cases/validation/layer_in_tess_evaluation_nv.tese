#version 450
// Issue 46, class 7: so does a tessellation evaluation shader, here with
// GL_NV_viewport_array2.
#extension GL_NV_viewport_array2 : require
layout(triangles) in;
void main() {
    gl_Position = gl_in[0].gl_Position;
    gl_Layer = 1;
    gl_ViewportIndex = 0;
}
