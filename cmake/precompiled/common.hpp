// The standard headers nearly every source here includes, precompiled once per
// target by safegi_precompile_common_headers() (cmake/SafeGIOptions.cmake).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>
