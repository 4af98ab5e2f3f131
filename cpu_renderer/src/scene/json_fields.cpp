#include <cmath>
#include <optional>
#include <sstream>

#include "scene/json_loader.hpp"

namespace safegi::render::json {

std::string short_dump(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

void JsonFields::fail(const JsonPath& path, const std::string& message) const {
  std::string where = path.text().empty() ? "" : path.text() + ": ";
  throw SceneError(display_name_ + ": " + where + message);
}

const Json& JsonFields::object(const Json& value, const JsonPath& path, std::initializer_list<std::string_view> allowed) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  for (const auto& [key, member] : value.items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || key == name;
    if (!known) {
      std::string list;
      for (std::string_view name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      fail(path.field(key), "unknown field (expected one of: " + list + ")");
    }
  }
  return value;
}

const Json& JsonFields::required(const Json& parent, const JsonPath& path, const char* name) {
  auto found = parent.find(name);
  if (found == parent.end()) fail(path, std::string("missing field '") + name + "'");
  return *found;
}

void JsonFields::require_float_range(const JsonPath& path, double value) const {
  if (!std::isfinite(value)) fail(path, "value is not finite");
  Real stored = static_cast<Real>(value);
  if (std::isinf(stored) || (stored == 0 && value != 0))
    fail(path, sizeof(Real) == 4
                   ? "value is out of float range (in SI units its magnitude must be 0 or lie in 1.4e-45 .. 3.4e38)"
                   : "value is out of double range (in SI units its magnitude must be 0 or lie in 4.9e-324 .. 1.8e308)");
}

double JsonFields::scalar(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
  Quantity quantity;
  if (value.is_number()) {
    if (!expected.is_dimensionless())
      fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (a number without unit)");
    quantity = {value.get<double>(), {}};
  } else if (value.is_string()) {
    std::string error;
    std::optional<Quantity> parsed = parse_quantity(value.get<std::string>(), error);
    if (!parsed) fail(path, "cannot read " + short_dump(value) + ": " + error);
    quantity = *parsed;
  } else if (value.is_object() && value.contains("value") && value["value"].is_number()) {
    object(value, path, {"value", "unit"});
    Unit unit = parse_unit_field(value, path);
    quantity = {value["value"].get<double>() * unit.to_reference, unit.dimension};
  } else {
    fail(path, "expected " + describe(expected) + ", got " + short_dump(value));
  }
  if (!(quantity.dimension == expected))
    fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (" +
                   dimension_name(quantity.dimension) + ")");
  require_float_range(path, quantity.value);
  return quantity.value;
}

Unit JsonFields::parse_unit_field(const Json& value, const JsonPath& path) {
  if (!value.contains("unit")) return Unit{};
  const Json& unit_json = value["unit"];
  if (!unit_json.is_string()) fail(path.field("unit"), "expected a unit string, got " + short_dump(unit_json));
  std::string error;
  std::optional<Unit> unit = parse_unit(unit_json.get<std::string>(), error);
  if (!unit) fail(path.field("unit"), "cannot read " + short_dump(unit_json) + ": " + error);
  return *unit;
}

Triple JsonFields::triple(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
  if (value.is_object() && value.contains("value") && value["value"].is_array()) {
    object(value, path, {"value", "unit"});
    const Json& components = value["value"];
    if (components.size() != 3) fail(path.field("value"), "expected 3 numbers, got " + short_dump(components));
    Unit unit = parse_unit_field(value, path);
    if (!(unit.dimension == expected))
      fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (" +
                     dimension_name(unit.dimension) + ")");
    Triple result;
    for (size_t i = 0; i < 3; ++i) {
      if (!components[i].is_number())
        fail(path.field("value").index(i), "expected a number, got " + short_dump(components[i]));
      result[i] = components[i].get<double>() * unit.to_reference;
      require_float_range(path.field("value").index(i), result[i]);
    }
    return result;
  }
  if (value.is_array()) {
    if (value.size() != 3) fail(path, "expected 3 components, got " + short_dump(value));
    Triple result;
    for (size_t i = 0; i < 3; ++i) result[i] = scalar(value[i], path.index(i), expected);
    return result;
  }
  fail(path, "expected 3 components of " + describe(expected) + ", got " + short_dump(value));
}

JsonFields::Rgb JsonFields::rgb_field(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
  bool is_triple = value.is_array() || (value.is_object() && value.contains("value") && value["value"].is_array());
  if (!is_triple) {
    Real grey = static_cast<Real>(scalar(value, path, expected));
    return {grey, grey, grey};
  }
  Triple t = triple(value, path, expected);
  return {static_cast<Real>(t[0]), static_cast<Real>(t[1]), static_cast<Real>(t[2])};
}

Reflectance JsonFields::reflectance(const Json& value, const JsonPath& path) {
  Reflectance albedo = typed_spectrum<dim::dimensionless>(value, path);
  for (int c = 0; c < 3; ++c)
    if (albedo[c] < 0 || albedo[c] > 1) fail(path, "reflectance must lie in [0, 1], got " + short_dump(value));
  return albedo;
}

int JsonFields::integer(const Json& value, const JsonPath& path, int minimum, int maximum) {
  if (!value.is_number_integer() || value.get<long long>() < minimum || value.get<long long>() > maximum)
    fail(path, "expected an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
                   "], got " + short_dump(value));
  return value.get<int>();
}

std::string JsonFields::string(const Json& value, const JsonPath& path) {
  if (!value.is_string()) fail(path, "expected a string, got " + short_dump(value));
  return value.get<std::string>();
}

bool JsonFields::boolean(const Json& value, const JsonPath& path) {
  if (!value.is_boolean()) fail(path, "expected true or false, got " + short_dump(value));
  return value.get<bool>();
}

Real JsonFields::number(const Json& value, const JsonPath& path, double minimum, double maximum) {
  double v = scalar(value, path, runtime_dim::none);
  if (!(v >= minimum && v <= maximum))
    fail(path, "expected a number in [" + short_number(minimum) + ", " + short_number(maximum) + "], got " +
                   short_dump(value));
  return static_cast<Real>(v);
}

std::string JsonFields::short_number(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

}  // namespace safegi::render::json
