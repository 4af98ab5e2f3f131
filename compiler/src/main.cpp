// safeglslc: see docs/safeglslc.md.
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "safegi/compiler/cli.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  std::vector<std::string> args(argv + 1, argv + argc);
  safegi::CliStreams io{std::cin, std::cout, std::cerr, isatty(fileno(stderr)) != 0};
  const int status = safegi::run_safeglslc(args, io);
  std::cout.flush();
  return status;
}
