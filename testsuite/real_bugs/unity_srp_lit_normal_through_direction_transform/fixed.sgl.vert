#version 450
#include <safegi/prelude.sgl>
// A render pipeline's vertex stage: directions (the tangent) go to world space
// with the model matrix, normals with the inverse transpose (the world-to-
// object matrix on the right).
space object;
space world;
space clip;

uniform map<object, world> objectToWorld;
uniform map<world, object> worldToObject;
uniform projmap<world, clip> viewProj;

in point<object> positionOS;
in normal<object> normalOS;
in direction<object> tangentOS;
out normal<world> normalWS;
out direction<world> tangentWS;

direction<world> TransformObjectToWorldDir(direction<object> d) {
    return normalize(mat3(objectToWorld) * d);
}

normal<world> TransformObjectToWorldNormal(normal<object> n) {
    return normalize(n * mat3(worldToObject));
}

void main() {
    normalWS = TransformObjectToWorldNormal(normalOS);
    tangentWS = TransformObjectToWorldDir(tangentOS);
    gl_Position = viewProj * (objectToWorld * vec4(positionOS, 1.0));
}
