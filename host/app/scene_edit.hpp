// scene_edit.hpp — the explorer's edit mode (`fractalis explore --edit DIR`): a scene project, as
// `fractalis new` writes one, watched while the explorer shows its scene.
//
// Saving the project's OpenCL (NAME.cl, NAME_surface.cl) swaps the scene's DE for the file's text
// at once, with no C build: the next frame compiles it, first without LLVM's optimizations (on
// screen within a second on two cores), then optimized (a second or two more). Saving its C (or a header, or its
// CMakeLists.txt) rebuilds and installs the plugin in the background, and the scene library
// reloads it as it reloads any rebuilt plugin. Either way the camera and parameter values stay.
// A change that does not compile, or whose DE crashes or hangs the render worker, is undone: the
// last good DE renders on, and the status line says what failed, in the user's own file and line
// (the kernel's #line directives name them). Changes settle first (an editor's save storm is one
// change), the folder is looked at about thirty times a second (a listing of a few files), and a
// folder that vanishes or cannot be read is said, and waited for.
#pragma once

#include "app/explorer.hpp"
#include "io/run_program.hpp"

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace fr {

struct SceneProject {
  std::filesystem::path dir;
  std::string scene_id;      // fractalis_add_scene(ID ...) in its CMakeLists.txt
  std::string de_file;       // DE_SOURCE: "NAME.cl"
  std::string surface_file;  // SURFACE_SOURCE, or ""
};

// Reads DIR/CMakeLists.txt. Nullopt with *error when DIR holds no scene project.
std::optional<SceneProject> read_scene_project(const std::filesystem::path& dir,
                                               std::string* error);

// The first compiler errors in a build's output ("file:line:col: error: ..."), at most `lines`
// of them, or the output's last lines when it has none.
std::string first_errors(const std::string& output, int lines);

class SceneEdit {
 public:
  // `cmake`: the CMake program that rebuilds the C (its build folder is DIR/build).
  SceneEdit(SceneProject project, std::filesystem::path cmake);
  ~SceneEdit();  // waits for a C build under way
  SceneEdit(const SceneEdit&) = delete;
  SceneEdit& operator=(const SceneEdit&) = delete;

  // Each frame, between explorer.update() and render(): looks at the files, applies a settled
  // change, and keeps or undoes the last one by what the explorer made of it (a DE that hung the
  // update's probe is undone before the render tries it).
  void poll(Explorer& explorer, double now_s);

  const SceneProject& project() const { return project_; }
  // One line for the overlay: what the last change did, or why it failed.
  const std::string& status() const { return status_; }
  bool failed() const { return failed_; }
  // OpenCL changes on screen (their first frame, a quick build), applied (the optimized build's
  // frame followed, and the change is kept), C builds that ended (either way): for tests and
  // benches.
  int opencl_shown() const { return opencl_shown_; }
  int opencl_applied() const { return opencl_applied_; }
  int c_builds() const { return c_builds_; }

 private:
  struct Stamp {
    uintmax_t size = 0;
    std::filesystem::file_time_type written{};
    bool operator==(const Stamp&) const = default;
  };
  // The project's files now (top level, sources only); false when the folder cannot be read.
  bool look(std::map<std::string, Stamp>* files, std::string* error) const;
  void apply_opencl(Explorer& explorer);
  void start_c_build();
  void say(const std::string& status, bool failed);

  SceneProject project_;
  std::filesystem::path cmake_;
  std::map<std::string, Stamp> stamps_;
  double next_look_s_ = 0;
  double first_change_s_ = -1, last_change_s_ = -1;
  bool opencl_changed_ = false, c_changed_ = false;
  bool folder_missing_ = false;
  // The change on trial: the scene before it, and the explorer's counts when it went in.
  std::shared_ptr<const LoadedScene> before_;
  uint64_t frames_at_apply_ = 0;
  uint64_t optimized_at_apply_ = 0;
  int failures_at_apply_ = 0;
  bool shown_ = false;  // its quick frame rendered
  // The C build in the background.
  std::thread build_;
  std::atomic<bool> build_done_{false};
  ProgramOutcome build_outcome_;
  std::string status_;
  bool failed_ = false;
  int opencl_shown_ = 0, opencl_applied_ = 0, c_builds_ = 0;
};

}  // namespace fr
