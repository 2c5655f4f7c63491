#include "plugin/plugin_loader.hpp"

#include "io/check.hpp"
#include "io/printable.hpp"
#include "plugin/descriptor_copy.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/plugin_library.hpp"
#include "plugin/scene_code.hpp"
#include "plugin/scene_host_process.hpp"

#include <map>

namespace fr {
namespace {

// plugins.isolation = "none": the plugin's constructors and callbacks run in this process.
LoadOutcome load_in_process(const std::filesystem::path& file, const PluginPolicy& policy) {
  LoadOutcome out;
  out.file = file;
  std::string error;
  const ReadableFile opened = open_plugin_file(file, policy.allow_writable, &error);
  if (!opened.valid()) {
    out.result = LoadResult::Refused;
    out.message = error;
    return out;
  }
  auto library = PluginLibrary::open(opened, file, &error);
  if (!library) {
    out.result = LoadResult::NotLoadable;
    out.message = printable(error);
    return out;
  }
  DescriptorCopy d =
      copy_descriptor(static_cast<const fr_scene_entry*>(library->symbol(FR_SCENE_ENTRY_SYMBOL)),
                      [&](const fr_scene_entry& e) { return init_error(e, file.string()); });
  library->set_deinit(d.deinit);
  out.result = d.result;
  out.message = d.message;
  if (d.result != LoadResult::Loaded) return out;
  auto scene = std::make_shared<LoadedScene>();
  scene->info = std::move(d.info);
  scene->file = file;
  scene->code = std::make_shared<InProcessCode>(std::move(library), d.create, d.destroy, d.update);
  out.scene = std::move(scene);
  return out;
}

std::vector<LoadOutcome> load_files(const std::vector<std::filesystem::path>& files,
                                    const PluginPolicy& policy) {
  if (policy.isolation == PluginIsolation::Process) return load_isolated(files, policy);
  std::vector<LoadOutcome> outcomes;
  for (const auto& f : files) outcomes.push_back(load_in_process(f, policy));
  return outcomes;
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
    case LoadResult::Refused:
      return "refused";
    case LoadResult::Crashed:
      return "crashed";
  }
  FR_CHECK(false, "a LoadResult without a name");
  return "unknown";  // not reached
}

LoadOutcome load_scene_plugin(const std::filesystem::path& file, const PluginPolicy& policy) {
  return load_files({file}, policy).front();
}

std::vector<LoadOutcome> load_scene_folder(const std::vector<std::filesystem::path>& folders,
                                           const PluginPolicy& policy) {
  std::vector<LoadOutcome> outcomes;
  std::map<std::string, std::filesystem::path> seen;  // id -> file that provides it
  for (const auto& folder : folders) {
    std::vector<std::filesystem::path> files;
    std::vector<LoadOutcome> skipped;
    for (const PluginFile& f : list_plugin_files(folder, policy.allow_writable)) {
      if (f.skip_reason.empty())
        files.push_back(f.path);
      else
        skipped.push_back({LoadResult::Refused, f.path, f.skip_reason, nullptr});
    }
    std::vector<LoadOutcome> loaded = load_files(files, policy);
    loaded.insert(loaded.end(), std::make_move_iterator(skipped.begin()),
                  std::make_move_iterator(skipped.end()));
    std::stable_sort(loaded.begin(), loaded.end(),
                     [](const LoadOutcome& a, const LoadOutcome& b) { return a.file < b.file; });
    for (LoadOutcome& o : loaded) {
      if (o.result == LoadResult::Loaded) {
        auto [it, fresh] = seen.emplace(o.scene->info.id, o.file);
        if (!fresh) {
          o.result = LoadResult::DuplicateId;
          o.message = "duplicate scene id '" + o.scene->info.id + "' (already provided by " +
                      printable(it->second.string()) + ")";
          o.scene.reset();
        }
      }
      outcomes.push_back(std::move(o));
    }
  }
  return outcomes;
}

}  // namespace fr
