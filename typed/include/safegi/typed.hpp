// The SafeGI typed library: physical dimensions and coordinate spaces checked at
// compile time, at no run-time cost. Define SAFEGI_UNCHECKED=1 (or link
// SafeGI::typed_unchecked) to compile the same code to plain floats and GLM vectors.
//
// Not included here, for what they cost every file: safegi/typed/reflection.hpp
// (describe<T>(): <string>, <vector>) and safegi/typed/format.hpp (std::format).
#pragma once

#include "safegi/typed/config.hpp"
#include "safegi/typed/dimension.hpp"
#include "safegi/typed/dimension_name.hpp"
#include "safegi/typed/frame.hpp"
#include "safegi/typed/geometric_normal.hpp"
#include "safegi/typed/map.hpp"
#include "safegi/typed/orientation.hpp"
#include "safegi/typed/print.hpp"
#include "safegi/typed/quantity.hpp"
#include "safegi/typed/radiometry.hpp"
#include "safegi/typed/ray.hpp"
#include "safegi/typed/space.hpp"
#include "safegi/typed/spectrum.hpp"
#include "safegi/typed/units.hpp"
