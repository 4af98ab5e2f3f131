#version 330 core
// A space declared again must be declared the same: with its origin at the eye, or not.
space view : eye;
space view;
void main() {}
