// The fractalis executable: everything is in the host library; see cli/cli.hpp.
#include "cli/cli.hpp"
#include "io/atomic_file.hpp"
#include "render/kernel_cache.hpp"

#include <iostream>

int main(int argc, char** argv) {
  // Ctrl-C or a kill while an output file is written leaves no temporary file.
  fr::install_temp_file_cleanup();
  // Compiled kernels go to fractalis's own cache folder, where they are kept bounded.
  fr::use_kernel_cache_dir();
  return fr::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
