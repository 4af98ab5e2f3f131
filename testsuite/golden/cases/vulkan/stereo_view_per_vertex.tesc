// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// GL_NV_stereo_view_rendering and GL_NVX_multiview_per_view_attributes add
// members to gl_PerVertex (gl_SecondaryPositionNV, gl_PositionPerViewNV, …),
// in gl_in[] and in a redeclared gl_out[] (glslang's spv.stereoViewRendering.tesc);
// without its extension a member is no member.
#version 450
#extension GL_NV_viewport_array2 : require
#extension GL_NV_stereo_view_rendering : require
layout(vertices = 4) out;
out gl_PerVertex {
  vec4 gl_SecondaryPositionNV;
  int gl_SecondaryViewportMaskNV[2];
} gl_out[4];
void main() {
  gl_out[gl_InvocationID].gl_SecondaryPositionNV = gl_in[1].gl_Position + gl_in[1].gl_SecondaryPositionNV;
  gl_out[gl_InvocationID].gl_SecondaryViewportMaskNV[0] = 1;
  vec4 v = gl_in[0].gl_PositionPerViewNV[0];
}
