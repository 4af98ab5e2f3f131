#version 330 core
// A base declared again must be declared the same: a ratio, or not.
dimension pixel : ratio;
dimension pixel;
void main() {}
