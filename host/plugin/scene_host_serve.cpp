// The scene-host side of scene_host_process.hpp: runs in fractalis-scene-host, never in the host.
#include "platform/shared_library.hpp"
#include "platform/system_facts.hpp"
#include "plugin/descriptor_copy.hpp"
#include "plugin/plugin_library.hpp"
#include "plugin/scene_host_process.hpp"
#include "plugin/wire_io.hpp"

#include <algorithm>

namespace fr {
namespace {

std::string reply_bytes(const CallOutcome& out, const WireWriter& result) {
  WireWriter w;
  w.u32(out.ok ? 1 : 0);
  w.str(out.error.substr(0, kMaxMessageBytes));
  write_messages(w, out.messages);
  return w.bytes() + result.bytes();
}

// Threads the scene host ran before any plugin code did: one on Linux; on Windows the system's
// loader may keep worker threads of its own from the start.
size_t threads_at_start = 1;

HostStats own_stats() {
  HostStats s;
  s.heap_bytes = heap_bytes_in_use();
  // Reported as 1 + the threads more than at the start: more than 1 are the plugin's.
  const size_t now = threads_in_this_process();
  s.threads = static_cast<uint32_t>(1 + (now > threads_at_start ? now - threads_at_start : 0));
  s.plugin_mappings = static_cast<uint32_t>(private_copy_mappings());
  return s;
}

}  // namespace

std::string init_error(const fr_scene_entry& entry, const std::string& file) {
  const CallOutcome out = run_entry_init(entry, file);
  return out.ok ? "" : out.error;
}

int run_scene_host(Channel& channel, ReadableFile plugin, const std::string& file) {
  threads_at_start = std::max<size_t>(threads_in_this_process(), 1);
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
