// fractalis-render-worker: compiles and runs scene kernels on behalf of fractalis, which starts
// it with a channel to it and the shared frame, each named by its handle on the command line
// (see worker/render_worker.hpp). Not meant to be run by hand.
#include "platform/child_process.hpp"
#include "render/kernel_cache.hpp"
#include "worker/render_wire.hpp"
#include "worker/render_worker.hpp"

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  fr::end_at_once_on_crash();
  std::string wire, device;
  fr::NativeHandle channel_handle = fr::kNoHandle, frame_handle = fr::kNoHandle;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--wire") == 0) wire = argv[i + 1];
    if (std::strcmp(argv[i], "--device") == 0) device = argv[i + 1];
    if (std::strcmp(argv[i], "--channel") == 0)
      channel_handle = fr::handle_from_argument(argv[i + 1]);
    if (std::strcmp(argv[i], "--frame") == 0) frame_handle = fr::handle_from_argument(argv[i + 1]);
  }
  if (wire.empty()) {
    std::fprintf(stderr,
                 "fractalis-render-worker renders scenes for fractalis; it is started by it.\n");
    return 2;
  }
  if (wire != std::to_string(fr::kRenderWireVersion)) return 126;
  if (channel_handle == fr::kNoHandle || frame_handle == fr::kNoHandle) return 2;
  // The only files a worker writes are the compiler's (the kernel cache: a few MB a program). A
  // preprocessor bomb writes its expansion there as it goes (1.8 GB in 40 s here): past this
  // size the worker ends with SIGXFSZ instead of filling the disk.
  fr::limit_written_file_size(fr::kWorkerFileSizeLimitBytes);
  fr::use_kernel_cache_dir();  // as fractalis's (a no-op when fractalis set it already)
  fr::Channel channel(channel_handle);
  return fr::run_render_worker(channel, frame_handle, device);
}

#if defined(__SANITIZE_ADDRESS__)
// The worker runs scene kernels, whose crashes are findings for fractalis to report ("crashed
// (SIGSEGV)"), not reports for AddressSanitizer to turn into exit status 1.
extern "C" const char* __asan_default_options() {
  return "handle_segv=0:handle_abort=0:handle_sigbus=0:detect_leaks=0";
}
#endif
