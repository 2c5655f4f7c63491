#include "plugin/plugin_loader.hpp"

#include "plugin/plugin_library.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <variant>

namespace fr {
namespace {

// Sizes of the ABI 1.0 structs: a plugin's struct may be larger (a newer minor), never smaller.
constexpr uint32_t kEntrySizeV1_0 = sizeof(fr_scene_entry);
constexpr uint32_t kSceneSizeV1_0 = sizeof(fr_scene_desc);
constexpr uint32_t kParamSizeV1_0 = sizeof(fr_param_desc);
constexpr uint32_t kCameraSizeV1_0 = sizeof(fr_camera);
constexpr uint32_t kLightSizeV1_0 = sizeof(fr_light);

// Copies the part of a plugin struct this host knows; fields beyond the plugin's size stay zero.
template <typename T>
T copy_struct(const T* from) {
  T to{};
  std::memcpy(&to, from, std::min<size_t>(sizeof(T), from->struct_size));
  to.struct_size = sizeof(T);
  return to;
}

struct Invalid {
  LoadResult result;
  std::string message;
};

bool is_identifier(const char* s, bool allow_dash) {
  if (!s || !(s[0] >= 'a' && s[0] <= 'z')) return false;
  size_t n = 0;
  for (; s[n]; ++n) {
    char c = s[n];
    bool ok =
        (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || (allow_dash && c == '-');
    if (!ok || n >= 63) return false;
  }
  return true;
}

std::string describe_value(const fr_value& v, int n) {
  std::ostringstream out;
  for (int i = 0; i < n; ++i) out << (i ? "," : "") << v.v[i];
  return out.str();
}

// Checks one parameter; returns an error sentence or "".
std::string check_param(const fr_param_desc& p, size_t index) {
  const std::string where =
      "parameter " + std::to_string(index) + (p.key ? " '" + std::string(p.key) + "'" : "");
  if (!is_identifier(p.key, false))
    return where + ": key must match [a-z][a-z0-9_]* (at most 63 bytes), got " +
           (p.key ? "'" + std::string(p.key) + "'" : std::string("null"));
  if (!p.name) return where + ": name is null";
  if (p.type < FR_PARAM_FLOAT || p.type > FR_PARAM_COLOR)
    return where + ": type " + std::to_string(p.type) +
           " is not one of float, int, bool, vec3, color";
  if ((p.flags & FR_PARAM_SPECIALIZE) && (p.flags & FR_PARAM_ANIMATABLE))
    return where + ": cannot be both SPECIALIZE and ANIMATABLE";
  const int n = (p.type == FR_PARAM_VEC3 || p.type == FR_PARAM_COLOR) ? 3 : 1;
  for (int i = 0; i < n; ++i) {
    double lo = p.min_value.v[i], def = p.default_value.v[i], hi = p.max_value.v[i];
    if (!std::isfinite(lo) || !std::isfinite(def) || !std::isfinite(hi) ||
        !(lo <= def && def <= hi))
      return where + ": needs finite min <= default <= max, got min " +
             describe_value(p.min_value, n) + ", default " + describe_value(p.default_value, n) +
             ", max " + describe_value(p.max_value, n);
    if ((p.type == FR_PARAM_INT || p.type == FR_PARAM_BOOL) &&
        (lo != std::floor(lo) || def != std::floor(def) || hi != std::floor(hi)))
      return where + ": int and bool limits must be whole numbers";
  }
  if (p.type == FR_PARAM_BOOL && (p.min_value.v[0] != 0 || p.max_value.v[0] != 1))
    return where + ": a bool's min must be 0 and max 1";
  if ((p.flags & FR_PARAM_LOG_SCALE) && !(p.min_value.v[0] > 0))
    return where + ": LOG_SCALE needs min > 0";
  return "";
}

// Validates the descriptor and copies it into host memory.
std::variant<SceneInfo, Invalid> copy_scene(const fr_scene_desc* desc_ptr) {
  auto invalid = [](std::string m) { return Invalid{LoadResult::InvalidScene, std::move(m)}; };
  if (!desc_ptr) return invalid("entry's scene pointer is null");
  if (desc_ptr->struct_size < kSceneSizeV1_0)
    return Invalid{LoadResult::StructTooSmall,
                   "fr_scene_desc struct_size " + std::to_string(desc_ptr->struct_size) +
                       " is smaller than ABI 1.0's " + std::to_string(kSceneSizeV1_0)};
  const fr_scene_desc d = copy_struct(desc_ptr);
  if (!d.id) return invalid("scene id is null (expected [a-z][a-z0-9_-]*)");
  if (!is_identifier(d.id, true))
    return invalid("scene id '" + std::string(d.id) +
                   "' must match [a-z][a-z0-9_-]* (at most 63 bytes)");
  const std::string id = d.id;
  if (!d.name) return invalid("scene '" + id + "': name is null");
  if (!d.version) return invalid("scene '" + id + "': version is null");
  if (!d.de_source)
    return invalid("scene '" + id + "': de_source is null (expected OpenCL C defining scene_de)");
  if (!(d.bounding_radius > 0 && std::isfinite(d.bounding_radius)))
    return invalid("scene '" + id + "': bounding_radius must be finite and > 0");
  if (d.param_count > 0 && !d.params)
    return invalid("scene '" + id + "': params is null but param_count > 0");
  if (d.light_count > 0 && !d.lights)
    return invalid("scene '" + id + "': lights is null but light_count > 0");

  SceneInfo info;
  info.id = id;
  info.name = d.name;
  info.version = d.version;
  info.author = d.author ? d.author : "";
  info.license = d.license ? d.license : "";
  info.description = d.description ? d.description : "";
  info.de_source = d.de_source;
  info.de_source_name = d.de_source_name ? d.de_source_name : id + ".cl";
  info.surface_source = d.surface_source ? d.surface_source : "";
  info.surface_source_name = d.surface_source_name ? d.surface_source_name : id + "_surface.cl";
  info.features = d.features;
  info.bounding_radius = d.bounding_radius;

  for (uint32_t i = 0; i < d.param_count; ++i) {
    const fr_param_desc* p_ptr = d.params[i];
    if (!p_ptr) return invalid("scene '" + id + "': parameter " + std::to_string(i) + " is null");
    if (p_ptr->struct_size < kParamSizeV1_0)
      return Invalid{LoadResult::StructTooSmall,
                     "scene '" + id + "': fr_param_desc " + std::to_string(i) + " struct_size " +
                         std::to_string(p_ptr->struct_size) + " is smaller than ABI 1.0's " +
                         std::to_string(kParamSizeV1_0)};
    const fr_param_desc p = copy_struct(p_ptr);
    if (std::string err = check_param(p, i); !err.empty())
      return invalid("scene '" + id + "': " + err);
    if (info.find_param(p.key) >= 0)
      return invalid("scene '" + id + "': parameter key '" + p.key + "' appears twice");
    ParamInfo param;
    param.key = p.key;
    param.name = p.name;
    param.group = p.group ? p.group : "";
    param.description = p.description ? p.description : "";
    param.type = p.type;
    param.flags = p.flags;
    param.default_value = p.default_value;
    param.min_value = p.min_value;
    param.max_value = p.max_value;
    info.params.push_back(std::move(param));
  }

  if (d.camera) {
    if (d.camera->struct_size < kCameraSizeV1_0)
      return Invalid{LoadResult::StructTooSmall, "scene '" + id + "': fr_camera struct_size " +
                                                     std::to_string(d.camera->struct_size) +
                                                     " is smaller than ABI 1.0's " +
                                                     std::to_string(kCameraSizeV1_0)};
    info.camera = copy_struct(d.camera);
    if (auto problem = check_camera(info.camera))
      return invalid("scene '" + id + "': default camera: " + *problem);
  } else {
    info.camera = fr_camera{sizeof(fr_camera), 0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 45};
  }
  for (uint32_t i = 0; i < d.light_count; ++i) {
    const fr_light* l = d.lights[i];
    if (!l) return invalid("scene '" + id + "': light " + std::to_string(i) + " is null");
    if (l->struct_size < kLightSizeV1_0)
      return Invalid{LoadResult::StructTooSmall,
                     "scene '" + id + "': fr_light " + std::to_string(i) + " struct_size " +
                         std::to_string(l->struct_size) + " is smaller than ABI 1.0's " +
                         std::to_string(kLightSizeV1_0)};
    fr_light light = copy_struct(l);
    if (light.kind != FR_LIGHT_DIRECTIONAL && light.kind != FR_LIGHT_POINT)
      return invalid("scene '" + id + "': light " + std::to_string(i) + " kind " +
                     std::to_string(light.kind) + " is neither directional (1) nor point (2)");
    if (!(light.attenuation >= 0) || !std::isfinite(light.attenuation) ||
        (light.attenuation > 0 && !(light.falloff > 0 && std::isfinite(light.falloff))))
      return invalid("scene '" + id + "': light " + std::to_string(i) +
                     " needs attenuation >= 0 and, when attenuation > 0, falloff > 0");
    info.lights.push_back(light);
  }
  return info;
}

}  // namespace

const char* load_result_name(LoadResult result) {
  switch (result) {
    case LoadResult::Loaded:
      return "loaded";
    case LoadResult::NotLoadable:
      return "not loadable";
    case LoadResult::NoEntrySymbol:
      return "no entry symbol";
    case LoadResult::WrongAbiMajor:
      return "wrong ABI major";
    case LoadResult::AbiTooNew:
      return "ABI too new";
    case LoadResult::StructTooSmall:
      return "struct too small";
    case LoadResult::InvalidScene:
      return "invalid scene";
    case LoadResult::DuplicateId:
      return "duplicate id";
  }
  return "unknown";
}

LoadOutcome load_scene_plugin(const std::filesystem::path& file) {
  LoadOutcome out;
  out.file = file;
  auto fail = [&](LoadResult r, std::string m) {
    out.result = r;
    out.message = std::move(m);
    return out;
  };
  std::string error;
  auto library = PluginLibrary::open(file, &error);
  if (!library) return fail(LoadResult::NotLoadable, error);

  const auto* entry = static_cast<const fr_scene_entry*>(library->symbol(FR_SCENE_ENTRY_SYMBOL));
  if (!entry)
    return fail(LoadResult::NoEntrySymbol, std::string("no exported symbol '") +
                                               FR_SCENE_ENTRY_SYMBOL +
                                               "' (expected a scene built with FR_SCENE_ENTRY)");
  if (entry->abi_major != FR_ABI_VERSION_MAJOR)
    return fail(LoadResult::WrongAbiMajor, "wrong ABI major: plugin " +
                                               std::to_string(entry->abi_major) + ", host " +
                                               std::to_string(FR_ABI_VERSION_MAJOR));
  if (entry->abi_minor > FR_ABI_VERSION_MINOR)
    return fail(LoadResult::AbiTooNew, "plugin needs ABI " + std::to_string(entry->abi_major) +
                                           "." + std::to_string(entry->abi_minor) + ", host has " +
                                           std::to_string(FR_ABI_VERSION_MAJOR) + "." +
                                           std::to_string(FR_ABI_VERSION_MINOR));
  if (entry->struct_size < kEntrySizeV1_0)
    return fail(LoadResult::StructTooSmall,
                "fr_scene_entry struct_size " + std::to_string(entry->struct_size) +
                    " is smaller than ABI 1.0's " + std::to_string(kEntrySizeV1_0));
  auto copied = copy_scene(entry->scene);
  if (auto* bad = std::get_if<Invalid>(&copied)) return fail(bad->result, bad->message);

  const fr_scene_desc desc = copy_struct(entry->scene);
  auto scene = std::make_shared<LoadedScene>();
  scene->info = std::move(std::get<SceneInfo>(copied));
  scene->file = file;
  scene->create = desc.create;
  scene->destroy = desc.destroy;
  scene->update = desc.update;
  scene->library = std::move(library);
  out.result = LoadResult::Loaded;
  out.scene = std::move(scene);
  return out;
}

std::vector<LoadOutcome> load_scene_folder(const std::vector<std::filesystem::path>& folders) {
  std::vector<LoadOutcome> outcomes;
  std::map<std::string, std::filesystem::path> seen;  // id -> file that provides it
  for (const auto& folder : folders) {
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
      if (e.path().extension() == ".so" && !e.is_directory()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      LoadOutcome o = load_scene_plugin(file);
      if (o.result == LoadResult::Loaded) {
        auto [it, fresh] = seen.emplace(o.scene->info.id, file);
        if (!fresh) {
          o.result = LoadResult::DuplicateId;
          o.message = "duplicate scene id '" + o.scene->info.id + "' (already provided by " +
                      it->second.string() + ")";
          o.scene.reset();
        }
      }
      outcomes.push_back(std::move(o));
    }
  }
  return outcomes;
}

}  // namespace fr
