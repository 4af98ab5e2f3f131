#version 450
#include <safegi/prelude.sgl>
// A picking ray against an object's bounding sphere: the world ray is brought
// into the object's space (whose matrix may scale) and the sphere test takes
// distances along a unit direction.
space world;
space object;

uniform map<world, object> worldToObject;
uniform point<world> rayOrigin;
uniform direction<world> rayDir;
uniform point<object> sphereCenter;
uniform float<length> sphereRadius;

out vec4 fragColor;

float<length> hitDistance(point<object> o, direction<object> d) {
    vec3 oc = sphereCenter - o;
    float tca = dot(oc, d);
    float d2 = dot(oc, oc) - tca * tca;
    float r2 = sphereRadius * sphereRadius;
    if (d2 > r2) return -sphereRadius;
    return tca - sqrt(r2 - d2);
}

void main() {
    vec3 o = (worldToObject * vec4(rayOrigin, 1.0)).xyz;
    vec3 d = normalize(mat3(worldToObject) * rayDir);
    float t = hitDistance(o, d);
    fragColor = vec4(vec3(t > 0.0 ? 1.0 : 0.0), 1.0);
}
