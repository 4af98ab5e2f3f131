#pragma once
// Raw OpenGL 4.5 core entry points through the glad loader that runtime_gl
// generates at build time. Include this only where raw GL calls are made; the
// typed API headers do not need it. Calls are valid once a safegi::gl::Context
// is current.
#include <glad/gl.h>
