#version 330 core
#include <safegi/prelude.sgl>
// Qt 3D's morph-target Phong material, vertex stage: position and normal are
// blended toward the morph target (interpolated, or added relative to the
// base), then the blended normal goes to world space by the model's normal
// matrix and the blended position by the model matrix.
space object;
space world;
space clip;

in point<object> vertexPosition;
in normal<object> vertexNormal;
in vec3 vertexPositionTarget;                     // a position, or an offset in relative mode
in vec3 vertexNormalTarget;                       // a normal, or an offset in relative mode

out point<world> worldPosition;
out normal<world> worldNormal;

uniform map<object, world> modelMatrix;
uniform mat3<object, world, normal> modelNormalMatrix;
uniform projmap<object, clip> modelViewProjection;
uniform float interpolator;

void main()
{
    point<object> morphPos;
    normal<object> morphNormal;
    if (interpolator > 0.0) {
        // normalized
        morphPos = mix(vertexPosition, vertexPositionTarget, interpolator);
        morphNormal = normalize(mix(vertexNormal, vertexNormalTarget, interpolator));
    } else {
        // relative
        morphPos = vertexPosition + vertexPositionTarget * abs(interpolator);
        morphNormal = normalize(vertexNormal + vertexNormalTarget * abs(interpolator));
    }

    worldNormal = normalize( modelNormalMatrix * morphPos );
    worldPosition = vec3( modelMatrix * vec4( morphPos, 1.0 ) );

    gl_Position = modelViewProjection * vec4( morphPos, 1.0 );
}
