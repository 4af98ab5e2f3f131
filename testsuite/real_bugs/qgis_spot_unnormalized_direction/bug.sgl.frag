#version 330 core
#include <safegi/prelude.sgl>
// A GIS viewer's Phong material with one spot light: the angle to the spot
// axis is tested through the cosine of unit vectors against the cosine of
// the cut-off angle.
space world;

uniform point<world> lightPosition;
uniform direction<world> lightDirection;           // the spot's axis
uniform float<angle in degree> lightCutOffAngle;
uniform spectrum<1> lightColor;
uniform float<1> lightIntensity;
uniform point<world> eyePosition;
uniform spectrum<1> kd;
uniform spectrum<1> ks;
uniform float<1> shininess;

in point<world, shaded> worldPosition;
in normal<world> worldNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(worldNormal);
    vec3 v = normalize(eyePosition - worldPosition);
    vec3 s = lightPosition - worldPosition;
    vec3 sn = normalize(s);
    float spotCos = dot(-s, lightDirection);
    float cutOffCos = cos(radians(lightCutOffAngle));
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    if (spotCos > cutOffCos) {
        float sDotN = max(dot(sn, n), 0.0);
        vec3 r = reflect(-sn, n);
        float rDotV = max(dot(r, v), 0.0);
        diffuse = lightIntensity * lightColor * kd * sDotN;
        specular = lightIntensity * lightColor * ks * pow(rDotV, shininess);
    }
    fragColor = vec4(diffuse + specular, 1.0);
}
