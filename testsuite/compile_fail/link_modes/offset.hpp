// One function, declared for both translation units of the mode-mixing test.
#pragma once
#include <safegi/typed/space.hpp>

safegi::point<safegi::spaces::world> offset(safegi::point<safegi::spaces::world> p);
