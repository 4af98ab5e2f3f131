#version 450
#include <safegi/prelude.sgl>
// A visualization library's iso-surface ray caster: at the hit, the surface
// normal is the volume's gradient by central differences one and a half
// voxels apart along each texture axis (the voxel size follows the volume's
// shape), then it lights the surface with a headlight.
space tex;                                   // the volume's texture coordinates

uniform sampler3D volume;
uniform vec3 volumeSize;                     // voxels per axis
uniform direction<tex> lightDir;             // toward the light, in texture space

in point<tex> hitCoord;                      // where the ray crossed the threshold
in vector<tex> stepCoord;                    // the ray's step, for the march
out vec4 fragColor;

void main() {
    vec3 gradientCoord = 1.5 * stepCoord;
    vec3 n;
    n.x = texture(volume, hitCoord + vec3(gradientCoord.x, 0.0, 0.0)).r
        - texture(volume, hitCoord - vec3(gradientCoord.x, 0.0, 0.0)).r;
    n.y = texture(volume, hitCoord + vec3(0.0, gradientCoord.y, 0.0)).r
        - texture(volume, hitCoord - vec3(0.0, gradientCoord.y, 0.0)).r;
    n.z = texture(volume, hitCoord + vec3(0.0, 0.0, gradientCoord.z)).r
        - texture(volume, hitCoord - vec3(0.0, 0.0, gradientCoord.z)).r;
    vec3 N = normalize(-n);
    float lambert = max(dot(N, lightDir), 0.0);
    fragColor = vec4(vec3(lambert), 1.0);
}
