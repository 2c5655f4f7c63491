#include "fuzz_targets.hpp"

#include "import/fract_file.hpp"
#include "import/mb2_import.hpp"

#include "cli/cli.hpp"
#include "cli/options.hpp"
#include "path/camera_path.hpp"
#include "plugin/descriptor_copy.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/scene_wire.hpp"
#include "settings/settings.hpp"

#include <cstring>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

namespace fr {

int fuzz_settings_file(const uint8_t* data, size_t size) {
  Settings settings;
  const auto problems =
      load_settings_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz", settings);
  for (const auto& p : problems) (void)p.to_string();
  return 0;
}

int fuzz_set_override(const uint8_t* data, size_t size) {
  Settings settings;
  const auto problems =
      apply_setting_override(std::string(reinterpret_cast<const char*>(data), size), settings);
  for (const auto& p : problems) (void)p.to_string();
  return 0;
}

int fuzz_command_line(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  // The public commands; "--help" is added last, so each stops after checking its options and
  // never renders, opens a window or writes a file.
  static const char* const kCommands[] = {"render",  "bench", "sweep", "list",
                                          "devices", "check", "cache", "explore"};
  std::vector<std::string> args = {kCommands[data[0] % std::size(kCommands)]};
  std::string current;
  for (size_t i = 1; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  args.push_back(current);
  for (std::string& a : args) {
    // --log-file opens its file before the command runs: keep the fuzzer from writing files.
    if (a.rfind("--log-file", 0) == 0) a = "--log-fil";
    // Each argument through the value parsers too.
    try {
      parse_size("--size", a);
    } catch (const UsageError&) {
    }
    try {
      parse_vec3("--eye", a);
    } catch (const UsageError&) {
    }
    try {
      parse_integer("--frames", a, 1, 1000000);
    } catch (const UsageError&) {
    }
  }
  args.push_back("--help");
  std::ostringstream out, err;
  run_cli(args, out, err);
  return 0;
}

int fuzz_scene_descriptor(const uint8_t* data, size_t size) {
  WireReader reader(std::string_view(reinterpret_cast<const char*>(data), size));
  SceneInfo info;
  if (read_scene_info(reader, &info)) {
    (void)check_scene_info(info);
    for (size_t i = 0; i < info.params.size(); ++i) (void)check_param_info(info.params[i], i);
  }
  return 0;
}

namespace {

// Takes values off the front of the input; past its end, zeros.
class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = v << 8 | u8();
    return v;
  }
  double f64() {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = bits << 8 | u8();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  // A small count most of the time, sometimes a huge one (the caps must hold).
  uint32_t count(uint32_t usual_max) {
    const uint8_t pick = u8();
    return pick < 240 ? pick % (usual_max + 1) : u32();
  }
  std::string text() {
    std::string s;
    const size_t n = u8() == 255 ? 5000 : u8() % 80;
    for (size_t i = 0; i < n; ++i) s += static_cast<char>(u8());  // may hold a NUL: shorter
    return s;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

// A struct_size as a plugin might give it: right, the 1.0 size, a bit off, or anything.
uint32_t struct_size(ByteReader& in, uint32_t right) {
  switch (in.u8() % 6) {
    case 3:
      return right - 8;
    case 4:
      return right + 8;
    case 5:
      return in.u32();
    default:
      return right;
  }
}

}  // namespace

int fuzz_scene_desc_copy(const uint8_t* data, size_t size) {
  ByteReader in(data, size);
  std::deque<std::string> strings;  // deque: the c_str() pointers handed out stay valid
  auto text = [&]() -> const char* {
    if (in.u8() % 8 == 0) return nullptr;
    strings.push_back(in.text());
    return strings.back().c_str();
  };
  auto value = [&] { return fr_value{{in.f64(), in.f64(), in.f64()}}; };

  // At most 300 real parameters and 20 lights lie behind the counts; a bigger count is a lie
  // the loader must refuse before it reads the array (so the arrays are sized to the cap).
  std::deque<fr_param_desc> params;
  std::vector<const fr_param_desc*> param_ptrs;
  const uint32_t param_count = in.count(8);
  for (uint32_t i = 0; i < std::min<uint32_t>(param_count, 300); ++i) {
    fr_param_desc p{};
    p.struct_size = struct_size(in, sizeof(fr_param_desc));
    p.type = static_cast<fr_param_type>(in.u8() % 7);
    p.flags = in.u8() % 4 == 0 ? in.u32() : in.u8() % 4;
    p.reserved = in.u8() % 16 == 0 ? 1 : 0;
    p.key = text();
    p.name = text();
    p.group = text();
    p.description = text();
    p.default_value = value();
    p.min_value = value();
    p.max_value = value();
    params.push_back(p);
    param_ptrs.push_back(in.u8() % 32 == 0 ? nullptr : &params.back());
  }
  param_ptrs.resize(300, nullptr);
  std::deque<fr_light> lights;
  std::vector<const fr_light*> light_ptrs;
  const uint32_t light_count = in.count(4);
  for (uint32_t i = 0; i < std::min<uint32_t>(light_count, 20); ++i) {
    fr_light l{};
    l.struct_size = struct_size(in, sizeof(fr_light));
    l.kind = in.u8() % 4;
    for (double& c : l.vector) c = in.f64();
    for (double& c : l.color) c = in.f64();
    l.intensity = in.f64();
    l.attenuation = in.f64();
    l.falloff = in.f64();
    lights.push_back(l);
    light_ptrs.push_back(in.u8() % 32 == 0 ? nullptr : &lights.back());
  }
  light_ptrs.resize(20, nullptr);
  fr_camera camera{};
  camera.struct_size = struct_size(in, sizeof(fr_camera));
  for (double& c : camera.eye) c = in.f64();
  for (double& c : camera.target) c = in.f64();
  for (double& c : camera.up) c = in.f64();
  camera.fov_deg = in.f64();

  fr_scene_desc desc{};
  desc.struct_size = struct_size(in, sizeof(fr_scene_desc));
  desc.reserved = in.u8() % 16 == 0 ? 1 : 0;
  desc.id = text();
  desc.name = text();
  desc.version = text();
  desc.author = text();
  desc.license = text();
  desc.description = text();
  desc.de_source = text();
  desc.de_source_name = text();
  desc.surface_source = text();
  desc.surface_source_name = text();
  desc.params = in.u8() % 16 == 0 ? nullptr : param_ptrs.data();
  desc.param_count = param_count;
  desc.light_count = light_count;
  desc.features = in.u8() % 8 == 0 ? in.u32() : in.u8() % 32;
  desc.camera = in.u8() % 4 == 0 ? nullptr : &camera;
  desc.lights = in.u8() % 16 == 0 ? nullptr : light_ptrs.data();
  desc.bounding_radius = in.f64();

  fr_scene_entry entry{};
  entry.abi_major = in.u8() % 8 == 0 ? in.u32() : FR_ABI_VERSION_MAJOR;
  entry.abi_minor = in.u8() % 8 == 0 ? in.u32() : in.u8() % 2;
  entry.struct_size = struct_size(in, sizeof(fr_scene_entry));
  entry.reserved = in.u8() % 16 == 0 ? 1 : 0;
  entry.scene = in.u8() % 32 == 0 ? nullptr : &desc;
  const DescriptorCopy copy = copy_descriptor(in.u8() % 32 == 0 ? nullptr : &entry);
  (void)copy.message.size();
  return 0;
}

int fuzz_camera_path(const uint8_t* data, size_t size) {
  static const SceneInfo scene = [] {
    SceneInfo s;
    s.id = "fuzz";
    const fr_param_type types[] = {FR_PARAM_FLOAT, FR_PARAM_INT, FR_PARAM_BOOL, FR_PARAM_VEC3,
                                   FR_PARAM_COLOR};
    const char* keys[] = {"power", "iterations", "animate", "offset", "tint"};
    for (int i = 0; i < 5; ++i) {
      ParamInfo p;
      p.key = p.name = keys[i];
      p.type = types[i];
      for (int c = 0; c < 3; ++c) {
        p.min_value.v[c] = types[i] == FR_PARAM_BOOL || types[i] == FR_PARAM_COLOR ? 0 : -10;
        p.max_value.v[c] = types[i] == FR_PARAM_BOOL || types[i] == FR_PARAM_COLOR ? 1 : 10;
      }
      s.params.push_back(p);
    }
    s.camera.struct_size = sizeof(fr_camera);
    s.camera.eye[2] = 5;
    s.camera.up[1] = 1;
    s.camera.fov_deg = 45;
    return s;
  }();
  std::vector<PathProblem> problems;
  const auto path = parse_camera_path(std::string(reinterpret_cast<const char*>(data), size),
                                      "fuzz.toml", scene, &problems);
  for (const auto& p : problems) (void)p.to_string();
  if (!path) return 0;
  // What the explorer would save reads back to the same keyframes.
  std::vector<PathProblem> again;
  const auto back =
      parse_camera_path(format_camera_path(*path, scene), "saved.toml", scene, &again);
  if (!back || back->keyframes.size() != path->keyframes.size()) __builtin_trap();
  for (size_t k = 0; k < path->keyframes.size(); ++k) {
    const Keyframe &a = path->keyframes[k], &b = back->keyframes[k];
    if (a.time_s != b.time_s || a.eye != b.eye || a.target != b.target || a.up != b.up ||
        a.fov_deg != b.fov_deg)
      __builtin_trap();
    for (size_t i = 0; i < scene.params.size(); ++i)
      for (int c = 0; c < scene.params[i].component_count(); ++c)
        if (a.params[i].v[c] != b.params[i].v[c]) __builtin_trap();
  }
  const double span = path->end_s() - path->start_s();
  for (int i = -1; i <= 33; ++i) {
    const PathSample s = sample_camera_path(*path, scene, path->start_s() + span * i / 32.0);
    (void)check_camera(s.camera);
  }
  return 0;
}

int fuzz_fract_file(const uint8_t* data, size_t size) {
  try {
    const FractFile f = parse_fract(std::string(reinterpret_cast<const char*>(data), size), "fuzz.fract");
    const Mb2Import imported = import_fract(f, "fuzz");
    if (imported.faithful() && imported.preset_toml.empty()) __builtin_trap();
  } catch (const FractError&) {
  }
  return 0;
}

}  // namespace fr
