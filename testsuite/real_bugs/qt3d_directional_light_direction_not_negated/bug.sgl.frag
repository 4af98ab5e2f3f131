#version 330 core
#include <safegi/prelude.sgl>
// Qt 3D's ADS (Phong) lighting include, directional light: the light's
// direction uniform is the way its light travels, so the vector toward the
// light, s, is its negation; the diffuse term is max(dot(s, n), 0) and the
// specular lobe is around the reflection of -s.
space world;

uniform direction<world, toward> lightDirection;  // where the light travels
uniform vec3 lightColor;
uniform float lightIntensity;
uniform point<world> eye;
uniform float shininess;

in point<world, shaded> worldPosition;
in normal<world> worldNormal;
out vec4 fragColor;

void adsModel(const in point<world, shaded> vpos, const in normal<world> vnormal, const in point<world> eyePos,
              const in float shine, out vec3 diffuseColor, out vec3 specularColor)
{
    diffuseColor = vec3(0.0);
    specularColor = vec3(0.0);

    vec3 n = normalize( vnormal );
    vec3 s = lightDirection;
    float diffuse = max( dot( s, n ), 0.0 );

    float specular = 0.0;
    if (diffuse > 0.0 && shine > 0.0) {
        vec3 r = reflect( -s, n );
        vec3 v = normalize( eyePos - vpos );
        float normFactor = ( shine + 2.0 ) / 2.0;
        specular = normFactor * pow( max( dot( r, v ), 0.0 ), shine );
    }

    diffuseColor += lightIntensity * diffuse * lightColor;
    specularColor += specular;
}

void main() {
    vec3 diffuseColor, specularColor;
    adsModel(worldPosition, worldNormal, eye, shininess, diffuseColor, specularColor);
    fragColor = vec4(diffuseColor + specularColor, 1.0);
}
