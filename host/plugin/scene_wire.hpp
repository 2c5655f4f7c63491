// scene_wire.hpp — the bytes that travel between the host and a scene-host process.
//
// Every message is a frame: a 32-bit kind, a 32-bit payload length, the payload. Payloads are
// flat sequences of fixed-size numbers and length-prefixed strings, in this machine's byte order
// (both ends are the same build). The reader checks every length against what is left and
// against a cap before it allocates, because the other end runs plugin code and may be broken.
#pragma once

#include "plugin/scene_info.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fr {

// Bumped whenever a message's layout changes; the host passes it to the scene host, which refuses
// to talk to another version.
constexpr uint32_t kSceneWireVersion = 3;
constexpr uint32_t kMaxFrameBytes = 16u << 20;

enum class WireKind : uint32_t {
  Loaded = 1,   // scene host -> host: LoadOutcome (see write_load_outcome)
  Create = 2,   // host -> scene host: (nothing)
  Update = 3,   // host -> scene host: u64 instance, SceneState
  Destroy = 4,  // host -> scene host: u64 instance
  Quit = 5,     // host -> scene host: exit now
  Reply = 6,    // scene host -> host: CallReply, then the call's result
  Stats = 7,    // host -> scene host: (nothing); reply: HostStats (fractalis check)
  Unload = 8,   // host -> scene host: destroy every instance, dlclose; reply: HostStats after
};

// What a scene-host process reports about itself (for `fractalis check`): heap in use, threads,
// and mappings of the plugin's private copy.
struct HostStats {
  uint64_t heap_bytes = 0;
  uint32_t threads = 0;
  uint32_t plugin_mappings = 0;
};

class WireWriter {
 public:
  void u32(uint32_t v) { raw(&v, sizeof v); }
  void i32(int32_t v) { raw(&v, sizeof v); }
  void u64(uint64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void str(std::string_view s);
  void raw(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// Reads what a WireWriter wrote. Any read past the end or over a cap sets failed() and returns
// zeros from then on, so callers check once at the end.
class WireReader {
 public:
  explicit WireReader(std::string_view bytes) : bytes_(bytes) {}
  uint32_t u32() { return fixed<uint32_t>(); }
  int32_t i32() { return fixed<int32_t>(); }
  uint64_t u64() { return fixed<uint64_t>(); }
  double f64() { return fixed<double>(); }
  std::string str(size_t cap);
  // Copies the next `n` bytes to `out` (what WireWriter::raw wrote); false when fewer are left.
  bool raw(void* out, size_t n) { return take(out, n); }
  bool failed() const { return failed_; }
  bool at_end() const { return at_ == bytes_.size(); }
  std::string_view rest() const { return bytes_.substr(at_); }

 private:
  template <typename T>
  T fixed() {
    T v{};
    if (!take(&v, sizeof v)) return T{};
    return v;
  }
  bool take(void* out, size_t n);
  std::string_view bytes_;
  size_t at_ = 0;
  bool failed_ = false;
};

// A message the plugin logged during a call.
struct PluginMessage {
  fr_log_level level = FR_LOG_INFO;
  std::string text;
};

void write_scene_info(WireWriter& w, const SceneInfo& info);
bool read_scene_info(WireReader& r, SceneInfo* info);  // false: malformed or over a cap

void write_scene_state(WireWriter& w, const SceneState& state);
// Reads a state with exactly `param_count` values and `light_count` lights.
bool read_scene_state(WireReader& r, size_t param_count, size_t light_count, SceneState* state);

void write_messages(WireWriter& w, const std::vector<PluginMessage>& messages);
bool read_messages(WireReader& r, std::vector<PluginMessage>* messages);

// The most messages one call may log, and the longest message, kept; the rest are dropped.
constexpr size_t kMaxMessagesPerCall = 16;
constexpr size_t kMaxMessageBytes = 1024;

}  // namespace fr
