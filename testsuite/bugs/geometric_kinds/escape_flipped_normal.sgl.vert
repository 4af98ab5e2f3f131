#version 330 core
#include <safegi/prelude.sgl>
// Normals, vectors and homogeneous points are different kinds.
space object;
space world;
space clip;

uniform map<object, world> worldFromObject;
uniform projmap<world, clip> clipFromWorld;

in point<object> position;
in normal<object> normalIn;
in vector<object> tangentIn;
out normal<world> worldNormal;
out vector<world> worldTangent;
out point<clip> ndcPos;

void main() {
    point<world> P = worldFromObject * position;
    normal<world> n = -(worldFromObject * normalIn);
    vector<world> t = worldFromObject * tangentIn;
    hpoint<clip> clipPos = clipFromWorld * P;
    point<clip> ndc = homogenize(clipPos);
    worldNormal = n;
    worldTangent = t;
    ndcPos = ndc;
    gl_Position = clipPos;
}
