#version 330 core
#include <safegi/prelude.sgl>
// A voxel game's entity vertex shader, normal-offset shadow bias: the scene is
// drawn shifted by the camera offset (positions near the player stay small),
// while the eye position is absolute. The distance from the player that sets
// the shadow map's texel size must be taken between points of one space: the
// vertex is moved back by the camera offset, and the distance is measured in
// the shadow map's plane (across the light direction).
space object;
space scene;                                // world shifted by -cameraOffset
space world;
space clip;

uniform map<object, scene> mWorld;
uniform projmap<object, clip> mWorldViewProj;
uniform point<world> eyePosition;
uniform vector<world> cameraOffset;
uniform direction<world> v_LightDirection;  // from the sun
uniform float<length> f_shadowfar;
uniform float f_textureresolution;
uniform float xyPerspectiveBias0;
uniform float xyPerspectiveBias1;

in point<object> inVertexPosition;
in normal<object> inVertexNormal;
out point<scene> worldPosition;
out float normalOffsetScale;
out float cosLight;

void main() {
    gl_Position = mWorldViewProj * vec4(inVertexPosition, 1.0);
    worldPosition = (mWorld * vec4(inVertexPosition, 1.0)).xyz;
    vec3 nNormal = normalize((mWorld * vec4(inVertexNormal, 0.0)).xyz);
    cosLight = max(1e-5, dot(nNormal, -v_LightDirection));

    vec3 eyeToVertex = worldPosition - eyePosition + cameraOffset;
    float distanceToPlayer = length(eyeToVertex - v_LightDirection * dot(eyeToVertex, v_LightDirection)) / f_shadowfar;
    float perspectiveFactor = distanceToPlayer * xyPerspectiveBias0 + xyPerspectiveBias1;
    float texelSize = f_shadowfar * perspectiveFactor * perspectiveFactor /
            (f_textureresolution * xyPerspectiveBias1 - perspectiveFactor * xyPerspectiveBias0);
    float slopeScale = clamp(pow(1.0 - cosLight * cosLight, 0.5), 0.0, 1.0);
    normalOffsetScale = texelSize * slopeScale;
}
