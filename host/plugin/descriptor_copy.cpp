#include "plugin/descriptor_copy.hpp"

#include "plugin/scene_checks.hpp"

#include <algorithm>
#include <cstring>
#include <functional>

namespace fr {
namespace {

// Sizes of the ABI 1.0 structs (frozen: tests/abi_layout_test.cpp): a plugin's struct may be
// larger (a newer minor) or as large as 1.0's, never smaller.
constexpr uint32_t kEntrySizeV1_0 = 24;
constexpr uint32_t kSceneSizeV1_0 = 160;
constexpr uint32_t kParamSizeV1_0 = 120;
constexpr uint32_t kCameraSizeV1_0 = 88;
constexpr uint32_t kLightSizeV1_0 = 80;

// Copies the part of a plugin struct this host knows; fields beyond the plugin's size stay zero.
template <typename T>
T copy_struct(const T* from) {
  T to{};
  std::memcpy(&to, from, std::min<size_t>(sizeof(T), from->struct_size));
  to.struct_size = sizeof(T);
  return to;
}

struct Failure {
  LoadResult result;
  std::string message;
};

std::string too_small(const std::string& what, uint32_t size, uint32_t v1_size) {
  return what + " struct_size " + std::to_string(size) + " is smaller than ABI 1.0's " +
         std::to_string(v1_size);
}

// Copies a NUL-terminated plugin string of at most `cap` bytes; never reads more than cap + 1.
bool copy_string(const char* s, size_t cap, std::string* out) {
  if (!s) {
    out->clear();
    return true;
  }
  const size_t n = strnlen(s, cap + 1);
  if (n > cap) return false;
  out->assign(s, n);
  return true;
}

}  // namespace

DescriptorCopy copy_descriptor(const fr_scene_entry* entry,
                               const std::function<std::string(const fr_scene_entry&)>& init) {
  DescriptorCopy out;
  auto fail = [&](LoadResult r, std::string m) {
    out.result = r;
    out.message = std::move(m);
    return out;
  };
  auto invalid = [&](std::string m) { return fail(LoadResult::InvalidScene, std::move(m)); };
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
                too_small("fr_scene_entry", entry->struct_size, kEntrySizeV1_0));
  if (entry->reserved != 0) return invalid("fr_scene_entry.reserved is not zero");
  // Fields past the plugin's struct_size (a 1.0 plugin's init, ...) read as null.
  const fr_scene_entry e = copy_struct(entry);
  if (init) {
    if (std::string error = init(e); !error.empty()) return invalid(error);
  }
  out.deinit = e.deinit;
  const fr_scene_desc* desc_ptr = e.scene;
  if (!desc_ptr) return invalid("entry's scene pointer is null");
  if (desc_ptr->struct_size < kSceneSizeV1_0)
    return fail(LoadResult::StructTooSmall,
                too_small("fr_scene_desc", desc_ptr->struct_size, kSceneSizeV1_0));
  const fr_scene_desc d = copy_struct(desc_ptr);
  if (!d.id) return invalid("scene id is null (expected [a-z][a-z0-9_-]*)");
  SceneInfo& info = out.info;
  if (!copy_string(d.id, kMaxIdBytes, &info.id))
    return invalid("scene id is longer than " + std::to_string(kMaxIdBytes) + " bytes");
  const std::string scene = "scene '" + info.id + "': ";
  if (d.reserved != 0) return invalid(scene + "fr_scene_desc.reserved is not zero");
  if (!d.name) return invalid(scene + "name is null");
  if (!d.version) return invalid(scene + "version is null");
  if (!d.de_source)
    return invalid(scene + "de_source is null (expected OpenCL C defining scene_de)");
  const struct {
    const char* field;
    const char* from;
    std::string* to;
    size_t cap;
  } strings[] = {
      {"name", d.name, &info.name, kMaxLabelBytes},
      {"version", d.version, &info.version, kMaxLabelBytes},
      {"author", d.author, &info.author, kMaxLabelBytes},
      {"license", d.license, &info.license, kMaxLabelBytes},
      {"description", d.description, &info.description, kMaxDescriptionBytes},
      {"tags", d.tags, &info.tags, kMaxLabelBytes},
      {"credit", d.credit, &info.credit, kMaxLabelBytes},
      {"de_source", d.de_source, &info.de_source, kMaxSourceBytes},
      {"de_source_name", d.de_source_name, &info.de_source_name, kMaxLabelBytes},
      {"surface_source", d.surface_source, &info.surface_source, kMaxSourceBytes},
      {"surface_source_name", d.surface_source_name, &info.surface_source_name, kMaxLabelBytes}};
  for (const auto& s : strings)
    if (!copy_string(s.from, s.cap, s.to))
      return invalid(scene + s.field + " is longer than " + std::to_string(s.cap) + " bytes");
  if (!d.de_source_name) info.de_source_name = info.id + ".cl";
  if (!d.surface_source_name) info.surface_source_name = info.id + "_surface.cl";
  info.features = d.features;
  info.bounding_radius = d.bounding_radius;

  // Counts are checked before the arrays they count are read.
  if (d.param_count > kMaxSceneParams)
    return invalid(scene + "param_count " + std::to_string(d.param_count) + " is more than " +
                   std::to_string(kMaxSceneParams));
  if (d.param_count > 0 && !d.params) return invalid(scene + "params is null but param_count > 0");
  if (d.light_count > FR_MAX_SCENE_LIGHTS)
    return invalid(scene + "light_count " + std::to_string(d.light_count) +
                   " is more than FR_MAX_SCENE_LIGHTS (" + std::to_string(FR_MAX_SCENE_LIGHTS) +
                   ")");
  if (d.light_count > 0 && !d.lights) return invalid(scene + "lights is null but light_count > 0");

  for (uint32_t i = 0; i < d.param_count; ++i) {
    const std::string where = scene + "parameter " + std::to_string(i);
    const fr_param_desc* p_ptr = d.params[i];
    if (!p_ptr) return invalid(where + " is null");
    if (p_ptr->struct_size < kParamSizeV1_0)
      return fail(LoadResult::StructTooSmall,
                  too_small(where + ": fr_param_desc", p_ptr->struct_size, kParamSizeV1_0));
    const fr_param_desc p = copy_struct(p_ptr);
    if (p.reserved != 0) return invalid(where + ": reserved is not zero");
    if (!p.key) return invalid(where + ": key is null");
    if (!p.name) return invalid(where + ": name is null");
    ParamInfo param;
    if (!copy_string(p.key, kMaxIdBytes, &param.key) ||
        !copy_string(p.name, kMaxLabelBytes, &param.name) ||
        !copy_string(p.group, kMaxLabelBytes, &param.group) ||
        !copy_string(p.description, kMaxDescriptionBytes, &param.description))
      return invalid(where + ": a string is longer than its limit");
    param.type = p.type;
    param.flags = p.flags;
    param.default_value = p.default_value;
    param.min_value = p.min_value;
    param.max_value = p.max_value;
    param.detail_ratio = p.detail_ratio;  // zero from a plugin built before 1.4 (copy_struct)
    if (p.type == FR_PARAM_CHOICE) {
      // Counted before the table is read; each name copied within its cap.
      if (p.choice_count == 0 || p.choice_count > kMaxChoices)
        return invalid(where + ": choice_count " + std::to_string(p.choice_count) +
                       " is not in 1.." + std::to_string(kMaxChoices));
      if (!p.choices) return invalid(where + ": choices is null but choice_count > 0");
      for (uint32_t c = 0; c < p.choice_count; ++c) {
        if (!p.choices[c]) return invalid(where + ": choice " + std::to_string(c) + " is null");
        std::string name;
        if (!copy_string(p.choices[c], kMaxIdBytes, &name))
          return invalid(where + ": choice " + std::to_string(c) + " is longer than " +
                         std::to_string(kMaxIdBytes) + " bytes");
        param.choices.push_back(std::move(name));
      }
    } else if (p.choices || p.choice_count || p.reserved2) {
      return invalid(where + ": choices, choice_count and reserved2 must be null and 0 unless "
                     "the type is choice");
    }
    info.params.push_back(std::move(param));
  }

  if (d.camera) {
    if (d.camera->struct_size < kCameraSizeV1_0)
      return fail(LoadResult::StructTooSmall,
                  too_small(scene + "fr_camera", d.camera->struct_size, kCameraSizeV1_0));
    info.camera = copy_struct(d.camera);
    if (info.camera.reserved != 0) return invalid(scene + "fr_camera.reserved is not zero");
  } else {
    info.camera = fr_camera{sizeof(fr_camera), 0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 45};
  }
  for (uint32_t i = 0; i < d.light_count; ++i) {
    const fr_light* l = d.lights[i];
    if (!l) return invalid(scene + "light " + std::to_string(i) + " is null");
    if (l->struct_size < kLightSizeV1_0)
      return fail(LoadResult::StructTooSmall, too_small(scene + "fr_light " + std::to_string(i),
                                                        l->struct_size, kLightSizeV1_0));
    info.lights.push_back(copy_struct(l));
  }
  if (auto problem = check_scene_info(info)) return invalid(*problem);
  out.create = d.create;
  out.destroy = d.destroy;
  out.update = d.update;
  out.result = LoadResult::Loaded;
  return out;
}

}  // namespace fr
