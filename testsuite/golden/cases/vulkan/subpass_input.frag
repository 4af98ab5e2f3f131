// RAW
// ARGS: -V -o /dev/null
// Input attachments (GL_KHR_vulkan_glsl): subpassInput and its MS and integer
// variants, read by subpassLoad. Issue 19, false-positive class 2.
#version 450
layout(input_attachment_index = 0, set = 0, binding = 0) uniform subpassInput inColor;
layout(input_attachment_index = 1, set = 0, binding = 1) uniform subpassInputMS inSamples;
layout(input_attachment_index = 2, set = 0, binding = 2) uniform usubpassInput inId;
layout(location = 0) out vec4 color;
void main() {
    color = subpassLoad(inColor) + subpassLoad(inSamples, 0) + vec4(subpassLoad(inId));
}
