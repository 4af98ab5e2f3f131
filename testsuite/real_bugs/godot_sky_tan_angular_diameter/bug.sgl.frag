#version 330 core
#include <safegi/prelude.sgl>
// A sky shader's sun disk: the light's angular diameter (set in degrees) is
// passed as an angle, and the disk is every view direction within half of it
// of the sun's direction.
space world;

uniform float<angle in degree> light_angular_distance;   // as set on the directional light
uniform direction<world> light0_direction;              // toward the sun
uniform spectrum<radiance> light0_color;
uniform spectrum<radiance> sky_color;

in direction<world> eyedir;
out vec4 color_out;

void main() {
    float light0_size = tan(radians(light_angular_distance));
    float sun_cos = cos(light0_size * 0.5);
    float sun_angle = dot(eyedir, light0_direction);
    spectrum<radiance> color = sun_angle > sun_cos ? light0_color : sky_color;
    color_out = vec4(color, 1.0);
}
