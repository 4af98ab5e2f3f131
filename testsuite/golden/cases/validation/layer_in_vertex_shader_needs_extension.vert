#version 450
// Issue 46, class 7: without one of the extensions gl_Layer is the geometry
// and fragment shaders' (glslang: "required extension not requested").
layout(location = 0) in vec4 position;
void main() {
    gl_Position = position;
    gl_Layer = 1;
}
