// fractalis-render-worker: compiles and runs scene kernels on behalf of fractalis, which starts
// it with a socket on descriptor 3 and the shared frame on descriptor 4 (see
// worker/render_worker.hpp). Not meant to be run by hand.
#include "render/kernel_cache.hpp"
#include "worker/render_wire.hpp"
#include "worker/render_worker.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  std::string wire, device;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--wire") == 0) wire = argv[i + 1];
    if (std::strcmp(argv[i], "--device") == 0) device = argv[i + 1];
  }
  if (wire.empty()) {
    std::fprintf(stderr,
                 "fractalis-render-worker renders scenes for fractalis; it is started by it.\n");
    return 2;
  }
  if (wire != std::to_string(fr::kRenderWireVersion)) return 126;
  // The only files a worker writes are the compiler's (the kernel cache: a few MB a program). A
  // preprocessor bomb writes its expansion there as it goes (1.8 GB in 40 s here): past this
  // size the worker ends with SIGXFSZ instead of filling the disk.
  const rlimit file_size{fr::kWorkerFileSizeLimitBytes, fr::kWorkerFileSizeLimitBytes};
  setrlimit(RLIMIT_FSIZE, &file_size);
  fr::use_kernel_cache_dir();  // as fractalis's (a no-op when fractalis set it already)
  return fr::run_render_worker(3, 4, device);
}

#if defined(__SANITIZE_ADDRESS__)
// The worker runs scene kernels, whose crashes are findings for fractalis to report ("crashed
// (SIGSEGV)"), not reports for AddressSanitizer to turn into exit status 1.
extern "C" const char* __asan_default_options() {
  return "handle_segv=0:handle_abort=0:handle_sigbus=0:detect_leaks=0";
}
#endif
