// safegi-gl-handles: writes a C++ header of typed handles for a program from its
// symbol table (docs/runtime-gl.md, "Generated handles"), or with --api vulkan
// for a runtime_vk compute pipeline (docs/runtime-vk.md).
//   safegi-gl-handles emission.program.json -o emission_handles.hpp --namespace shaders::emission
//   safegi-gl-handles --api vulkan scale.json -o scale_handles.hpp --namespace shaders::scale
// Exit codes: 0 written, 1 the table is invalid or has a type without C++ spelling, 2 usage or I/O.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <sstream>

#include "safegi/symbol_table/error.hpp"
#include "safegi/symbol_table/handles_header.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Writes a C++ header of typed runtime_gl (or runtime_vk) handles from a SafeGI symbol table"};
  std::string input, output = "-";
  std::vector<std::string> cpp_names;
  safegi::gl::HandlesHeaderOptions options;
  app.add_option("table", input, "symbol table (JSON, schema v1 or v2)")->required();
  app.add_option("-o,--output", output, "header to write ('-': standard output)");
  app.add_option("--namespace", options.namespace_name, "C++ namespace of the handles struct");
  app.add_option("--struct", options.struct_name, "name of the handles struct");
  app.add_option("--cpp", cpp_names, "NAME=TYPE: C++ spelling of a base dimension or space");
  std::string api = "opengl";
  app.add_option("--api", api, "opengl (runtime_gl handles) or vulkan (runtime_vk handles and block layouts)")
      ->check(CLI::IsMember({"opengl", "vulkan"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  options.api = api == "vulkan" ? safegi::gl::Client::vulkan : safegi::gl::Client::opengl;
  for (const auto& mapping : cpp_names) {
    const auto equals = mapping.find('=');
    if (equals == std::string::npos || equals == 0) {
      std::cerr << "safegi-gl-handles: error: --cpp expects NAME=TYPE, found '" << mapping << "'\n";
      return 2;
    }
    options.cpp_names[mapping.substr(0, equals)] = mapping.substr(equals + 1);
  }
  std::ifstream file(input);
  if (!file) {
    std::cerr << "safegi-gl-handles: error: cannot read " << input << '\n';
    return 2;
  }
  std::stringstream text;
  text << file.rdbuf();
  options.origin = input.substr(input.find_last_of('/') + 1);
  std::string header;
  try {
    header = safegi::gl::generate_handles_header(safegi::gl::parse_symbol_table(text.str(), input), options);
  } catch (const safegi::gl::Error& error) {
    std::cerr << error.what() << '\n';
    return 1;
  }
  if (output == "-") {
    std::cout << header;
    return 0;
  }
  std::ofstream out(output);
  if (!(out << header)) {
    std::cerr << "safegi-gl-handles: error: cannot write " << output << '\n';
    return 2;
  }
  return 0;
}
