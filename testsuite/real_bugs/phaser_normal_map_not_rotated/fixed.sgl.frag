#version 330 core
#include <safegi/prelude.sgl>
// A 2D HTML5 game framework's light pipeline: a sprite's normal map holds
// normals in the sprite's own (texture) frame; a rotated sprite's normals are
// turned into the scene's frame by the sprite's rotation before the cosine
// with the direction toward a point light above the scene plane.
space sprite;
space scene;

uniform sampler2D uNormSampler;                    // normal map, [0, 1] encoded
uniform mat3<sprite, scene, rigid> uSpriteRotation;
uniform point<scene> uLightPosition;               // z: height above the plane
uniform spectrum<irradiance / proj> uLightColor;
uniform spectrum<brdf> uDiffuse;
uniform spectrum<radiance> uAmbient;

in vec2 outTexCoord;
in point<scene, shaded> outWorldPos;
out vec4 fragColor;

void main() {
    normal<sprite> nSprite = normalize(texture(uNormSampler, outTexCoord).rgb * 2.0 - 1.0);
    vec3 n = uSpriteRotation * nSprite;
    vec3 l = normalize(uLightPosition - outWorldPos);
    float cosL = max(dot(n, l), 0.0);
    spectrum<radiance> L = uAmbient + uDiffuse * uLightColor * cosL;
    fragColor = vec4(L, 1.0);
}
