// The fractalis executable: everything is in the host library; see cli/cli.hpp.
#include "cli/cli.hpp"

#include <iostream>

int main(int argc, char** argv) {
  return fr::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
