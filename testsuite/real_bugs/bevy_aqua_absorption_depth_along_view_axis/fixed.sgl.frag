#version 450
#include <safegi/prelude.sgl>
// A water plugin's absorption: light from the floor seen through the water
// is attenuated by Beer-Lambert over the distance it travels in the water,
// from the surface point to the floor point behind it along the eye ray, not
// only the difference of their depths along the camera's forward axis.
space view : eye;

uniform sampler2D sceneColor;
uniform sampler2D<point<view>> scenePosition;     // view-space position behind the water
uniform spectrum<inv_length> absorption;
uniform vec2 invScreenSize;

in point<view, shaded> surfacePos;                // view-space water surface point
out vec4 fragColor;

void main() {
    vec2 uv = gl_FragCoord.xy * invScreenSize;
    point<view> floorPos = texture(scenePosition, uv).xyz;
    float<length> waterPath = distance(floorPos, surfacePos);
    vec3 transmittance = exp(-absorption * waterPath);
    fragColor = vec4(texture(sceneColor, uv).rgb * transmittance, 1.0);
}
