#version 330 core
struct Light {
  centroid vec3 position;
};
uniform Light light;
out vec4 color;
void main() {
  in float weight = 1.0;
  color = vec4(light.position * weight, 1.0);
}
