#include "app/scene_edit.hpp"

#include "io/printable.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <iterator>
#include <sstream>

namespace fr {
namespace {

bool read_text(const std::filesystem::path& file, std::string* text) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

// The word after `key` in `text` (CMake arguments: separated by spaces and newlines), or "".
std::string word_after(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  if (at == std::string::npos) return "";
  std::istringstream rest(text.substr(at + key.size()));
  std::string word;
  rest >> word;
  while (!word.empty() && (word.back() == ')' || word.back() == '"')) word.pop_back();
  while (!word.empty() && word.front() == '"') word.erase(0, 1);
  return word;
}

bool is_source(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  return ext == ".c" || ext == ".h" || ext == ".cl" || file.filename() == "CMakeLists.txt";
}

}  // namespace

std::optional<SceneProject> read_scene_project(const std::filesystem::path& dir,
                                               std::string* error) {
  std::string lists;
  if (!read_text(dir / "CMakeLists.txt", &lists)) {
    *error = dir.string() + " holds no CMakeLists.txt: not a scene project (`fractalis new` makes one)";
    return std::nullopt;
  }
  SceneProject p;
  p.dir = dir;
  p.scene_id = word_after(lists, "fractalis_add_scene(");
  p.de_file = word_after(lists, "DE_SOURCE ");
  p.surface_file = word_after(lists, "SURFACE_SOURCE ");
  if (p.scene_id.empty() || p.de_file.empty()) {
    *error = (dir / "CMakeLists.txt").string() +
             ": no fractalis_add_scene(ID ... DE_SOURCE FILE.cl): not a scene project";
    return std::nullopt;
  }
  return p;
}

std::string first_errors(const std::string& output, int lines) {
  std::istringstream in(output);
  std::string line, found, last;
  int count = 0;
  std::vector<std::string> tail;
  while (std::getline(in, line)) {
    if (count < lines && (line.find(": error:") != std::string::npos ||
                          line.find(": fatal error:") != std::string::npos)) {
      if (!found.empty()) found += '\n';
      found += line;
      ++count;
    }
    tail.push_back(line);
    if (tail.size() > static_cast<size_t>(lines)) tail.erase(tail.begin());
  }
  if (!found.empty()) return found;
  for (const std::string& t : tail) {
    if (!last.empty()) last += '\n';
    last += t;
  }
  return last;
}

SceneEdit::SceneEdit(SceneProject project, std::filesystem::path cmake)
    : project_(std::move(project)), cmake_(std::move(cmake)) {
  std::string error;
  if (!look(&stamps_, &error)) say(error, true);
  status_ = "editing " + project_.dir.string() + ": save " + project_.de_file + " or the C";
}

SceneEdit::~SceneEdit() {
  if (build_.joinable()) build_.join();
}

void SceneEdit::say(const std::string& status, bool failed) {
  if (status == status_ && failed == failed_) return;
  status_ = status;
  failed_ = failed;
  if (failed)
    spdlog::error("{}", status);
  else
    spdlog::info("{}", status);
}

bool SceneEdit::look(std::map<std::string, Stamp>* files, std::string* error) const {
  files->clear();
  std::error_code ec;
  std::filesystem::directory_iterator it(project_.dir, ec);
  if (ec) {
    *error = project_.dir.string() + " cannot be read (" + ec.message() +
             "): the last good build renders on; waiting for the folder to come back";
    return false;
  }
  for (; it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const std::filesystem::path file = it->path();
    if (!is_source(file) || !it->is_regular_file(ec)) continue;
    Stamp s;
    s.size = std::filesystem::file_size(file, ec);
    if (!ec) s.written = std::filesystem::last_write_time(file, ec);
    if (!ec) (*files)[file.filename().string()] = s;
  }
  return true;
}

void SceneEdit::poll(Explorer& explorer, double now_s) {
  SceneSlot& slot = explorer.current();
  // The change on trial: kept once a frame rendered with it, undone if it did not compile or
  // took the render worker down.
  if (before_ && slot.scene->info.id == project_.scene_id) {
    const bool broke = explorer.worker_failures() > failures_at_apply_ || !slot.error.empty();
    if (broke) {
      const std::string why = slot.error.empty() ? "it ended the render worker" : slot.error;
      slot.scene = before_;
      before_.reset();
      slot.error.clear();
      explorer.scene_code_changed();
      say(project_.de_file + " did not work, so the last good one renders on:\n" + why, true);
    } else if (explorer.optimized_frames_rendered() > optimized_at_apply_ &&
               explorer.frames_rendered() > frames_at_apply_ + 1) {
      // The quick build's frame and then the optimized build's: kept.
      before_.reset();
      ++opencl_applied_;
      say("applied " + project_.de_file, false);
    } else if (explorer.frames_rendered() > frames_at_apply_ && !shown_) {
      shown_ = true;
      ++opencl_shown_;
      say("showing " + project_.de_file + " (a quick build; the optimized one follows)", false);
    }
  }
  // A C build that ended: the library reloads the installed plugin by itself.
  if (build_.joinable() && build_done_) {
    build_.join();
    ++c_builds_;
    if (build_outcome_.ok)
      say("rebuilt and installed " + project_.scene_id + "; the explorer reloads it", false);
    else
      say("the C build failed (" + build_outcome_.how + "), the last good build renders on:\n" +
              first_errors(build_outcome_.output, 4),
          true);
  }
  if (now_s < next_look_s_) return;
  next_look_s_ = now_s + 0.03;
  std::map<std::string, Stamp> now;
  std::string error;
  if (!look(&now, &error)) {
    folder_missing_ = true;
    say(error, true);
    return;
  }
  if (folder_missing_) {
    folder_missing_ = false;
    say("the project folder is back", false);
  }
  for (const auto& [name, stamp] : now) {
    const auto old = stamps_.find(name);
    if (old != stamps_.end() && old->second == stamp) continue;
    const bool opencl = std::filesystem::path(name).extension() == ".cl";
    (opencl ? opencl_changed_ : c_changed_) = true;
    if (first_change_s_ < 0) first_change_s_ = now_s;
    last_change_s_ = now_s;
  }
  stamps_ = std::move(now);
  if (first_change_s_ < 0) return;
  // Settled: nothing new for 0.12 s, or changing for 0.6 s already (an editor that saves ten
  // times a second still shows its latest text twice a second, not ten builds a second).
  if (now_s - last_change_s_ < 0.12 && now_s - first_change_s_ < 0.6) return;
  if (c_changed_) {
    if (build_.joinable()) return;  // one build at a time: this change waits for it
    c_changed_ = opencl_changed_ = false;  // the build embeds the OpenCL as it is now
    first_change_s_ = last_change_s_ = -1;
    before_.reset();
    start_c_build();
    return;
  }
  opencl_changed_ = false;
  first_change_s_ = last_change_s_ = -1;
  if (slot.scene->info.id != project_.scene_id) {
    say("changed " + project_.de_file + "; switch to " + project_.scene_id + " to see it", false);
    return;
  }
  apply_opencl(explorer);
}

void SceneEdit::apply_opencl(Explorer& explorer) {
  SceneSlot& slot = explorer.current();
  std::string de, surface;
  if (!read_text(project_.dir / project_.de_file, &de) ||
      (!project_.surface_file.empty() &&
       !read_text(project_.dir / project_.surface_file, &surface))) {
    say("cannot read " + project_.de_file + " (or its surface file) in " + project_.dir.string() +
            ": the last good build renders on",
        true);
    return;
  }
  const SceneInfo& old = slot.scene->info;
  if (de == old.de_source && (project_.surface_file.empty() || surface == old.surface_source))
    return;  // saved unchanged
  auto changed = std::make_shared<LoadedScene>(*slot.scene);
  changed->info.de_source = de;
  if (!project_.surface_file.empty()) changed->info.surface_source = surface;
  // On trial until a frame renders with it (poll). No probe of the DE alone first: that is a
  // kernel build of its own before the frame's (a third of a second on two cores). The frame's
  // build reports a compile error as well, with the user's file and line, and the render worker
  // gives a changed DE's first frame, and the probe at the eye that follows it, a short limit
  // (render_worker.hpp's kFirstLimitOfAnEditS): one that never returns is said within seconds.
  if (!before_) before_ = slot.scene;
  slot.scene = changed;
  slot.error.clear();
  frames_at_apply_ = explorer.frames_rendered();
  optimized_at_apply_ = explorer.optimized_frames_rendered();
  failures_at_apply_ = explorer.worker_failures();
  shown_ = false;
  explorer.scene_code_changed(/*quick_first_frame=*/true);
  say("compiling " + project_.de_file + " ...", false);
}

void SceneEdit::start_c_build() {
  say("building " + project_.scene_id + "'s C ...", false);
  build_done_ = false;
  const std::string build = (project_.dir / "build").string();
  build_ = std::thread([this, build] {
    build_outcome_ = run_program(cmake_, {"--build", build});
    if (build_outcome_.ok) {
      ProgramOutcome install = run_program(cmake_, {"--install", build});
      if (!install.ok) build_outcome_ = install;
    }
    build_done_ = true;
  });
}

}  // namespace fr
