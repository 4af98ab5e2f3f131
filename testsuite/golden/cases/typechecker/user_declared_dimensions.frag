#version 330 core
dimension mass;
dimension length;
dimension density = mass / length^3;
unit gram : mass = 0.001;
out vec4 c;
void main() {
  float<mass> m = 5.0 * gram;
  float<length^3> v = float<length^3>(2.0);
  float<density> rho = m / v;
  c = vec4(rho);
}
