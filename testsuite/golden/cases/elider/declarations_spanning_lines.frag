#version 330 core
dimension length;
dimension
  area = length
       ^ 2;
unit mm : length =
  0.001;
out vec4 c;
void main() { float<area> a = 2.0 * mm * mm; c = vec4(a); }
