// fractalis-scene-host: runs one scene plugin's code on behalf of the fractalis host, which
// starts it with a channel to it and the plugin file open, each named by its handle on the
// command line (see plugin/scene_host_process.hpp). Not meant to be run by hand.
#include "platform/child_process.hpp"
#include "plugin/scene_host_process.hpp"
#include "plugin/scene_wire.hpp"

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  fr::end_at_once_on_crash();
  std::string wire, file;
  fr::NativeHandle channel_handle = fr::kNoHandle, plugin_handle = fr::kNoHandle;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--wire") == 0) wire = argv[i + 1];
    if (std::strcmp(argv[i], "--file") == 0) file = argv[i + 1];
    if (std::strcmp(argv[i], "--channel") == 0)
      channel_handle = fr::handle_from_argument(argv[i + 1]);
    if (std::strcmp(argv[i], "--plugin") == 0)
      plugin_handle = fr::handle_from_argument(argv[i + 1]);
  }
  if (wire.empty()) {
    std::fprintf(stderr,
                 "fractalis-scene-host runs scene plugins for fractalis; it is started by it.\n");
    return 2;
  }
  if (wire != std::to_string(fr::kSceneWireVersion)) return 126;
  if (channel_handle == fr::kNoHandle || plugin_handle == fr::kNoHandle) return 2;
  fr::Channel channel(channel_handle);
  std::string error;
  fr::ReadableFile plugin = fr::ReadableFile::adopt(plugin_handle, &error);
  if (!plugin.valid())
    std::fprintf(stderr, "fractalis-scene-host: the plugin: %s\n", error.c_str());
  return fr::run_scene_host(channel, std::move(plugin), file);
}

#if defined(__SANITIZE_ADDRESS__)
// The scene host runs plugin code, whose crashes are findings for the host to report ("crashed
// (SIGSEGV)"), not reports for AddressSanitizer to turn into exit status 1.
extern "C" const char* __asan_default_options() {
  return "handle_segv=0:handle_abort=0:handle_sigbus=0:detect_leaks=0";
}
#endif
