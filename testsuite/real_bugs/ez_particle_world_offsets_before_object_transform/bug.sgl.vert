#version 450
#include <safegi/prelude.sgl>
// A game engine's stretched particle quads: the particle's centre is in the
// effect's object space, while the quad's axes (the particle's tangent and
// its cross product with the camera's forward axis) are world directions, so
// the corner offsets are added after the centre is taken to world space.
space object;
space world;
space clip;

uniform map<object, world> ObjectToWorldMatrix;
uniform projmap<world, clip> WorldToScreenMatrix;
uniform direction<world> CameraDirForwards;

layout(location = 0) in point<object> inPosition;
layout(location = 1) in direction<world> inTangentXws;
layout(location = 2) in float<length> inSize;
layout(location = 3) in vec2 inQuadTexCoord;
layout(location = 4) in float stretch;

void main() {
    vec3 axisDir = inTangentXws;
    vec3 orthoDir = normalize(cross(inTangentXws, CameraDirForwards));
    vec3 offsetRight = orthoDir * ((inQuadTexCoord.x - 0.5) * inSize);
    vec3 offsetUp = axisDir * ((1.0 - inQuadTexCoord.y) * inSize * stretch);
    point<world> worldPosition = (ObjectToWorldMatrix * vec4(inPosition + offsetRight + offsetUp, 1.0)).xyz;
    gl_Position = WorldToScreenMatrix * vec4(worldPosition, 1.0);
}
