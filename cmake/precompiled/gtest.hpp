// GoogleTest, precompiled once per test program (cmake/SafeGIOptions.cmake).
#pragma once
#include <gtest/gtest.h>
