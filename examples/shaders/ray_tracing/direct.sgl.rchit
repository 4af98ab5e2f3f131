#version 460
#extension GL_EXT_ray_tracing : require
// One sample of a rectangular area light at the hit point: the light is
// sampled by area, so its pdf is converted to the projected solid angle at the
// hit with the r^2 / cos Jacobian before it divides the estimate; a shadow ray
// (payload 1, answered by direct_shadow.sgl.rmiss) says whether the sample is seen.
#include <safegi/prelude.sgl>

space world;

layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;
layout(set = 0, binding = 3) uniform Light {
    point<world>       corner;
    vector<world>      edgeU;
    vector<world>      edgeV;
    normal<world>      normal;
    spectrum<radiance> Le;
    float<area>        area;
} light;
layout(shaderRecordEXT, std430) buffer Material {
    spectrum<brdf> Kd;
    normal<world>  N;        // the geometry's normal (planar patches)
} material;

layout(location = 0) rayPayloadInEXT spectrum<radiance> radiance;
layout(location = 1) rayPayloadEXT float<1> visibility;
hitAttributeEXT vec2 barycentrics;       // uniform random numbers for this example

void main() {
    point<world> P = gl_WorldRayOriginEXT + gl_WorldRayDirectionEXT * gl_HitTEXT;
    point<world> Y = light.corner + light.edgeU * float<1>(barycentrics.x) + light.edgeV * float<1>(barycentrics.y);
    vector<world> toLight = Y - P;
    float<area> r2 = dot(toLight, toLight);
    direction<world> wi = normalize(toLight);
    float<proj> cosX = max(dot(normalize(material.N), wi), 0.0);
    float<proj> cosY = max(-dot(normalize(light.normal), wi), 0.0);
    if (cosX <= 0.0 || cosY <= 0.0) {
        radiance = spectrum<radiance>(0.0);
        return;
    }
    visibility = 0.0;
    traceRayEXT(scene, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT, 0xff, 0, 0, 1, P,
                0.001 * meter, wi, sqrt(r2) - 0.001 * meter, 1);
    float<pdf_area> pdfA = 1.0 / light.area;
    // Area measure at Y -> projected solid angle at P: the r^2 / cos Jacobian,
    // where the cosine at the light turns area into solid angle.
    float<pdf_projected_solid_angle> pdfW = pdfA * r2 / (cosX * float<solid_angle>(cosY));
    radiance = material.Kd * light.Le * visibility / pdfW;
}
