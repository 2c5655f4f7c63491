// The scene-host side of scene_host_process.hpp: runs in fractalis-scene-host, never in the host.
#include "platform/system_facts.hpp"
#include "plugin/descriptor_copy.hpp"
#include "plugin/plugin_library.hpp"
#include "plugin/scene_host_process.hpp"
#include "plugin/wire_io.hpp"

#include <dirent.h>

#include <cstdio>
#include <cstring>

namespace fr {
namespace {

std::string reply_bytes(const CallOutcome& out, const WireWriter& result) {
  WireWriter w;
  w.u32(out.ok ? 1 : 0);
  w.str(out.error.substr(0, kMaxMessageBytes));
  write_messages(w, out.messages);
  return w.bytes() + result.bytes();
}

size_t count_lines(const char* file, const char* part) {
  FILE* f = std::fopen(file, "r");
  if (!f) return 0;
  char line[4096];
  size_t n = 0;
  while (std::fgets(line, sizeof line, f))
    if (!part || std::strstr(line, part)) ++n;
  std::fclose(f);
  return n;
}

HostStats own_stats() {
  HostStats s;
  s.heap_bytes = heap_bytes_in_use();
  size_t threads = 0;
  if (DIR* d = opendir("/proc/self/task")) {
    while (const dirent* e = readdir(d))
      if (e->d_name[0] != '.') ++threads;
    closedir(d);
  }
  s.threads = static_cast<uint32_t>(threads);
  s.plugin_mappings = static_cast<uint32_t>(count_lines("/proc/self/maps", "fractalis-plugin"));
  return s;
}

}  // namespace

std::string init_error(const fr_scene_entry& entry, const std::string& file) {
  const CallOutcome out = run_entry_init(entry, file);
  return out.ok ? "" : out.error;
}

int run_scene_host(Channel& channel, ReadableFile plugin, const std::string& file) {
  std::string error;
  std::shared_ptr<PluginLibrary> library =
      plugin.valid() ? PluginLibrary::open(plugin, file, &error) : nullptr;
  if (!plugin.valid()) error = "the plugin file handed over is not open";
  plugin = ReadableFile();  // closed: the private copy is loaded
  DescriptorCopy d;
  if (!library) {
    d.result = LoadResult::NotLoadable;
    d.message = error;
  } else {
    d = copy_descriptor(static_cast<const fr_scene_entry*>(library->symbol(FR_SCENE_ENTRY_SYMBOL)),
                        [&](const fr_scene_entry& e) { return init_error(e, file); });
    library->set_deinit(d.deinit);
  }
  WireWriter loaded;
  loaded.u32(static_cast<uint32_t>(d.result));
  loaded.str(d.message.substr(0, kMaxMessageBytes));
  if (d.result == LoadResult::Loaded) {
    loaded.u32((d.create ? 1u : 0u) | (d.update ? 2u : 0u) | (d.destroy ? 4u : 0u));
    write_scene_info(loaded, d.info);
  }
  if (!write_frame(channel, WireKind::Loaded, loaded.bytes()) || d.result != LoadResult::Loaded)
    return 0;

  auto code = std::make_unique<InProcessCode>(library, d.create, d.destroy, d.update);
  for (;;) {
    WireKind kind{};
    std::string request;
    if (read_frame(channel, -1, &kind, &request) != ReadStatus::Ok) return 0;
    WireReader r(request);
    WireWriter result;
    CallOutcome out;
    switch (kind) {
      case WireKind::Create: {
        uint64_t instance = 0;
        out = code->create(&instance);
        result.u64(instance);
        break;
      }
      case WireKind::Update: {
        const uint64_t instance = r.u64();
        SceneState state;
        if (!read_scene_state(r, d.info.params.size(), d.info.lights.size(), &state)) return 2;
        out = code->update(instance, state);
        write_scene_state(result, state);
        break;
      }
      case WireKind::Destroy:
        code->destroy(r.u64());
        out.ok = true;
        break;
      case WireKind::Unload:
        code->destroy_all();
        code.reset();
        library.reset();  // the last reference: dlclose
        [[fallthrough]];
      case WireKind::Stats: {
        const HostStats stats = own_stats();
        result.u64(stats.heap_bytes);
        result.u32(stats.threads);
        result.u32(stats.plugin_mappings);
        out.ok = true;
        if (!code && kind == WireKind::Unload) {
          if (!write_frame(channel, WireKind::Reply, reply_bytes(out, result))) return 0;
          // Nothing is loaded any more: answer Stats until told to quit.
          for (;;) {
            if (read_frame(channel, -1, &kind, &request) != ReadStatus::Ok ||
                kind != WireKind::Stats)
              return 0;
            WireWriter again;
            const HostStats s = own_stats();
            again.u64(s.heap_bytes);
            again.u32(s.threads);
            again.u32(s.plugin_mappings);
            if (!write_frame(channel, WireKind::Reply, reply_bytes(out, again))) return 0;
          }
        }
        break;
      }
      case WireKind::Quit:
        return 0;
      default:
        return 2;
    }
    if (!write_frame(channel, WireKind::Reply, reply_bytes(out, result))) return 0;
  }
}

}  // namespace fr
