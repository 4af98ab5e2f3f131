#version 450
#include <safegi/prelude.sgl>
// Skinning: the normal goes by the inverse transpose of the blended matrix's
// linear part. Transposing that normal matrix once more gives the inverse,
// which takes values the other way; the hint drops the extra transpose.
space bind;
space object;

uniform map<bind, object> blended;
layout(location = 1) in normal<bind> bindNormal;
out normal<object> skinnedNormal;

void main() {
    mat3 normalMatrix = transpose(inverse(mat3(blended)));
    normal<object> right = normalize(normalMatrix * bindNormal);
    skinnedNormal = normalize(transpose(normalMatrix) * bindNormal);
    skinnedNormal = right;
}
