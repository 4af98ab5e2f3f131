// Issue 46, class 2: `{}` needs '#extension GL_EXT_null_initializer' (glslang:
// "'empty { } initializer' : not supported for this version or the enabled extensions").
#version 450
layout(location = 0) out vec4 color;
struct Cmd { uint count; vec2 dir; };
void main() {
    Cmd c = {};
    color = vec4(c.dir, 0.0, 1.0);
}
