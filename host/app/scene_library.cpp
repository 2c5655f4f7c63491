#include "app/scene_library.hpp"

#include "io/printable.hpp"
#include "plugin/plugin_loader.hpp"
#include "render/kernel_assembly.hpp"
#include "render/scene_vetting.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <future>
#include <thread>

namespace fr {

std::string SceneEvent::to_string() const {
  const std::string name = printable(file.filename().string());
  switch (kind) {
    case Kind::Added:
      return "added '" + scene_id + "' from " + name;
    case Kind::Reloaded:
      return "reloaded '" + scene_id + "' from " + name;
    case Kind::Kept:
      return "kept the running '" + scene_id + "': " + reason;
    case Kind::Skipped:
      return "skipped " + printable(file.string()) + ": " + reason;
    case Kind::Removed:
      return "'" + scene_id + "' was removed; it runs until you switch away";
  }
  return reason;
}

void log_scene_event(const SceneEvent& event) {
  if (event.is_failure())
    spdlog::warn("{}", event.to_string());
  else
    spdlog::info("{}", event.to_string());
}

bool make_slot(std::shared_ptr<const LoadedScene> scene, SceneSlot* slot, std::string* error) {
  slot->state = make_default_state(scene->info);
  slot->instance = SceneInstance::create(scene, error);
  if (!slot->instance) return false;
  if (!slot->instance->update(slot->state, 0, error)) return false;
  slot->scene = std::move(scene);
  return true;
}

SceneLibrary::SceneLibrary(std::vector<std::filesystem::path> folders, const PluginPolicy& policy,
                           const RenderSettings& settings, RenderWorker& worker,
                           std::vector<SceneEvent>* events, bool vet_in_background)
    : policy_(policy), vet_settings_(settings), worker_(worker) {
  const std::vector<LoadOutcome> outcomes = load_scene_folder(folders, policy_);
  // Test renders of the scenes not vetted before, as many at a time as there are cores: each
  // compiles a kernel within plugins.build_timeout_s, and forty compiling at once on two cores
  // (a first start with empty caches) ran every one of them past it.
  vet_queue_ = std::make_unique<VetQueue>(settings, worker_.device().name, policy_);
  for (const LoadOutcome& o : outcomes) {
    auto skipped = [&](const std::string& why) {
      events->push_back({SceneEvent::Kind::Skipped, "", o.file, why});
      failed_files_.push_back(events->back());
    };
    if (!o.scene) {
      skipped(o.message);
      continue;
    }
    SceneSlot slot;
    std::string error;
    if (!make_slot(o.scene, &slot, &error)) {
      skipped(error);
      continue;
    }
    const uint64_t hash = VettedScenes::content_hash(o.file);
    if (!vetted_.contains(hash, settings)) {
      slot.preparing = true;
      vet_queue_->add(o.file, hash);
    }
    worker_.name_scene_file(o.scene->info.id, o.file);
    events->push_back({SceneEvent::Kind::Added, o.scene->info.id, o.file, ""});
    slots_.push_back(std::move(slot));
  }
  if (!vet_in_background) {
    vet_queue_->wait_idle();
    // Nobody holds an index yet: a scene that failed leaves the list, as if it never loaded.
    for (SceneEvent& e : take_vet_results()) {
      std::erase_if(slots_, [&](const SceneSlot& s) { return s.scene->file == e.file; });
      std::erase_if(*events, [&](const SceneEvent& a) { return a.file == e.file; });
      events->push_back(e);
      failed_files_.push_back(e);
    }
  }
  if (vet_queue_->outstanding() == 0) vet_queue_.reset();
  for (const auto& f : folders) watchers_.push_back(std::make_unique<PluginWatcher>(f));
}

std::vector<SceneEvent> SceneLibrary::take_vet_results() {
  std::vector<SceneEvent> failures;
  if (!vet_queue_) return failures;
  for (VetDone& done : vet_queue_->take_done()) {
    // The slot still waiting for this file's result (a hot reload may have replaced it since).
    const auto slot = std::find_if(slots_.begin(), slots_.end(), [&](const SceneSlot& s) {
      return s.preparing && s.scene->file == done.file;
    });
    if (slot == slots_.end()) continue;
    slot->preparing = false;
    ++generation_;
    if (done.result.ok) {
      vetted_.insert(done.hash, vet_settings_);
      continue;
    }
    slot->refused = true;
    slot->error = done.result.error;
    failures.push_back({SceneEvent::Kind::Skipped, "", done.file, done.result.error});
  }
  return failures;
}

void SceneLibrary::prioritize(int index) {
  if (vet_queue_ && index >= 0 && index < static_cast<int>(slots_.size()) &&
      slots_[index].preparing)
    vet_queue_->prioritize(slots_[index].scene->file);
}

int SceneLibrary::preparing() const {
  return static_cast<int>(
      std::count_if(slots_.begin(), slots_.end(), [](const SceneSlot& s) { return s.preparing; }));
}

int SceneLibrary::find(const std::string& id) const {
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].scene->info.id == id) return static_cast<int>(i);
  return -1;
}

SceneEvent SceneLibrary::add_or_replace(const std::filesystem::path& file,
                                        const RenderSettings& settings) {
  LoadOutcome o = load_scene_plugin(file, policy_);
  // The slot this file fills: its own, else (a new file) a removed scene's with the same id.
  int by_file = -1, by_id = -1;
  for (size_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].scene->file == file) by_file = static_cast<int>(i);
    if (o.scene && slots_[i].scene->info.id == o.scene->info.id) by_id = static_cast<int>(i);
  }
  const int index = by_file >= 0 ? by_file : by_id;
  auto keep_old = [&](const std::string& why) {
    if (index >= 0) {
      slots_[index].error = why;
      return SceneEvent{SceneEvent::Kind::Kept, slots_[index].scene->info.id, file, why};
    }
    return SceneEvent{SceneEvent::Kind::Skipped, "", file, why};
  };
  if (!o.scene) return keep_old(o.message);
  // A file may not take over a scene another file provides.
  if (by_id >= 0 && by_id != by_file && !slots_[by_id].removed)
    return keep_old("refused " + printable(file.filename().string()) + ": it declares scene id '" +
                    o.scene->info.id + "', which " +
                    printable(slots_[by_id].scene->file.filename().string()) + " provides");

  SceneSlot fresh;
  std::string error;
  if (!make_slot(o.scene, &fresh, &error)) return keep_old(error);
  if (index >= 0) {
    // Keep the user's values (by key) and camera.
    const SceneSlot& old = slots_[index];
    fresh.state.params = rebind_params(old.scene->info, old.state.params, o.scene->info);
    fresh.state.camera = old.state.camera;
    fresh.state.time_s = old.state.time_s;
  }
  // Build the kernel now, so a scene that does not compile never replaces a working one.
  // (At a wide width that the scene's code does not build at, the renderer falls back to
  // kPacketLanes, and so does this test.)
  worker_.name_scene_file(o.scene->info.id, file);
  const auto build = [&](int lanes) {
    const auto k = assemble_render_kernel(o.scene->info, fresh.state.params,
                                          make_kernel_config(o.scene->info, settings, lanes));
    worker_.build(o.scene->info, k.source, k.build_options, k.description);
  };
  const int lanes = worker_.lanes_for(settings);
  try {
    build(lanes);
  } catch (const KernelBuildError& e) {
    if (settings.lanes != 0 || lanes <= kPacketLanes) return keep_old(e.what());
    try {
      build(kPacketLanes);
    } catch (const std::exception&) {
      return keep_old(e.what());  // the wide build's error: the first one the scene met
    }
  } catch (const std::exception& e) {
    return keep_old(e.what());
  }
  // A DE that never returns would hang the explorer's first frame: a test render in a child
  // process with a time limit first (once per file content and kernel shape).
  const uint64_t hash = VettedScenes::content_hash(file);
  if (!vetted_.contains(hash, settings)) {
    const VetResult vet = vet_scene(file, settings, worker_.device().name, policy_);
    if (!vet.ok) return keep_old(vet.error);
    vetted_.insert(hash, settings);
  }
  const std::string id = o.scene->info.id;
  if (index >= 0) {
    slots_[index] = std::move(fresh);
    return {SceneEvent::Kind::Reloaded, id, file, ""};
  }
  slots_.push_back(std::move(fresh));
  return {SceneEvent::Kind::Added, id, file, ""};
}

std::vector<SceneEvent> SceneLibrary::poll(double now_s, const RenderSettings& settings) {
  // The background test renders that finished: the scenes that failed are said (and kept, as
  // refused slots, so that no index moves under the explorer).
  std::vector<SceneEvent> events = take_vet_results();
  if (vet_queue_ && vet_queue_->outstanding() == 0 && preparing() == 0) vet_queue_.reset();
  for (auto& w : watchers_) {
    for (const PluginChange& c : w->poll(now_s)) {
      if (c.kind == PluginChange::Kind::Removed) {
        if (std::erase_if(failed_files_, [&](const SceneEvent& f) { return f.file == c.file; }))
          ++generation_;
        for (auto& slot : slots_)
          if (slot.scene->file == c.file && !slot.removed) {
            slot.removed = true;
            events.push_back({SceneEvent::Kind::Removed, slot.scene->info.id, c.file, ""});
          }
        continue;
      }
      events.push_back(add_or_replace(c.file, settings));
    }
  }
  // What failed now and what no longer does.
  for (const SceneEvent& e : events) {
    std::erase_if(failed_files_, [&](const SceneEvent& f) { return f.file == e.file; });
    if (e.kind == SceneEvent::Kind::Skipped) failed_files_.push_back(e);
  }
  if (!events.empty()) ++generation_;
  return events;
}

void SceneLibrary::drop_if_removed(int index) {
  if (index >= 0 && index < static_cast<int>(slots_.size()) && slots_[index].removed) {
    slots_.erase(slots_.begin() + index);
    ++generation_;
  }
}

}  // namespace fr
