#version 330 core
#include <safegi/prelude.sgl>
// A camera and a shadow-casting light: model, view and projection matrices
// compose into one projective map per eye; a rigid view keeps normals simple.
space object;
space world;
space view;
space clip;
space light_view;
space light_clip;

uniform map<object, world> worldFromObject;            // may scale: not rigid
uniform rigidmap<world, view> viewFromWorld;           // the camera: rotation + translation
uniform projmap<view, clip> clipFromView;              // perspective projection
uniform rigidmap<world, light_view> lightViewFromWorld;
uniform projmap<light_view, light_clip> lightClipFromLightView;

in point<object> position;
in normal<object> normalIn;
out point<view> viewPos;
out normal<view> viewNormal;
out hpoint<light_clip> shadowCoord;

void main() {
    map<object, view> viewFromObject = viewFromWorld * worldFromObject;
    projmap<object, clip> clipFromObject = clipFromView * viewFromWorld * worldFromObject;
    projmap<object, light_clip> lightClipFromObject = lightClipFromLightView * viewFromWorld * worldFromObject;
    viewPos = viewFromObject * position;
    viewNormal = normalize(viewFromObject * normalIn);
    shadowCoord = lightClipFromObject * position;
    gl_Position = clipFromObject * position;
}
