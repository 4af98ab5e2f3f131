#version 330 core
#include <safegi/prelude.sgl>
// A space combat game's fighter beams: a beam turret may fire at a target
// only inside its field of fire, a cone whose full angle the ship table gives
// in degrees. The test compares the cosine of the angle to the target with the
// cosine of half the cone's angle, converted to radians (the game's
// fl_radians); here it colours the targets the turret can hit.
space world;

uniform point<world> turretPos;
uniform direction<world> turretNormal;          // the cone's axis
uniform float<angle in degree> fieldOfFire;     // full cone angle, from the table
uniform point<world> targetPos;
out vec4 fragColor;

void main() {
    vec3 toTarget = normalize(targetPos - turretPos);
    float cosToTarget = dot(turretNormal, toTarget);
    float cosHalfFov = cos(radians(fieldOfFire) * 0.5);
    bool canFire = cosToTarget >= cosHalfFov;
    fragColor = canFire ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0);
}
