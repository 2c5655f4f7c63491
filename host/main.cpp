// The fractalis executable: everything is in the host library; see cli/cli.hpp.
#include "cli/cli.hpp"
#include "io/atomic_file.hpp"
#include "mpi/mpi_world.hpp"
#include "render/kernel_cache.hpp"

#include <iostream>

int main(int argc, char** argv) {
  // Started by mpirun or srun: one rank of an MPI job (mpi/mpi_world.hpp); else one process.
  std::string problem;
  if (!fr::start_mpi(&argc, &argv, &problem)) {
    std::cerr << "fractalis: error: " << problem << "\n";
    return 2;
  }
  // Ctrl-C or a kill while an output file is written leaves no temporary file.
  fr::install_temp_file_cleanup();
  // Compiled kernels go to fractalis's own cache folder, where they are kept bounded.
  fr::use_kernel_cache_dir();
  const int status =
      fr::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  fr::finish_mpi();
  return status;
}

#if defined(__SANITIZE_ADDRESS__)
// Sanitizer builds only (the tests set the same: tests/sanitizer_options.cpp). With FFmpeg's,
// OpenEXR's and stb_image's libraries linked in, a process that loads
// PoCL has more dynamic-TLS modules than GCC 12's LeakSanitizer tracks correctly: at exit it
// scans a stale dynamic-TLS range and its tracer crashes ("Tracer caught signal 11 ... does not
// work under ptrace"), failing every run. Not intercepting __tls_get_addr avoids that range;
// leaks are still detected (the root set keeps the static TLS and every stack and global).
extern "C" const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
#endif
