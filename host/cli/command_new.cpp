// `fractalis new NAME [--from ID] [--dir DIR]`: a scene project written, built and installed in
// one command (authoring/scene_project.hpp writes the files; this finds the sources, runs CMake
// and says what to edit next).
#include "authoring/scene_project.hpp"
#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/echo.hpp"
#include "io/run_program.hpp"
#include "platform/child_process.hpp"
#include "platform/user_folders.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

// Where the sources `new` starts from are, in the source tree and installed (host/CMakeLists.txt
// gives these to this file alone).
#ifndef FRACTALIS_SCENE_SOURCES_SOURCE_DIR
#error "host/CMakeLists.txt defines the scene sources' folders for this file"
#endif

namespace fr {
namespace {

// Runs `program arguments...` with its output on our stderr (the user sees CMake's progress);
// true when it exited with status 0, else *error says how it ended.
bool run(const std::filesystem::path& program, const std::vector<std::string>& arguments,
         std::string* error) {
  ChildSpec spec;
  spec.program = program;
  spec.arguments = arguments;
  spec.stdout_to = own_stderr();
  spec.stderr_to = own_stderr();
  std::unique_ptr<ChildProcess> child = ChildProcess::start(spec, error);
  if (!child) return false;
  child->wait(-1);
  if (child->exit_status() == 0) return true;
  *error = program.filename().string() + " " + (arguments.empty() ? "" : arguments[0]) + " " +
           child->how_it_ended();
  return false;
}

// The SDK's CMake package folder: the source tree's sdk/cmake, or an installed prefix's
// lib[/<triplet>]/cmake/FractalisSDK.
std::filesystem::path sdk_package_folder() {
  const std::filesystem::path source = FRACTALIS_SDK_SOURCE_DIR "/cmake";
  const std::filesystem::path installed = shipped_folder(source, FRACTALIS_SDK_CMAKE_INSTALL_DIR);
  std::error_code ec;
  if (std::filesystem::exists(installed / "FractalisSDKConfig.cmake", ec)) return installed;
  return {};
}

}  // namespace

int command_new(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = plugin_option_specs();
  const std::vector<OptionSpec> more = {
      {"from", "ID", false, "start from the sources of this in-tree scene (default: the template)"},
      {"dir", "DIR", false,
       "where the project goes (default: your scene-source folder, <data>/fractalis/scene-sources/NAME)"},
      {"no-build", nullptr, false, "write the project only; build it yourself with CMake"},
      {"help", nullptr, false, "show this help"},
  };
  specs.insert(specs.end(), more.begin(), more.end());
  std::vector<std::string> rest = args;
  std::string name;
  // NAME is the one word that is not an option (nor an option's value).
  for (size_t i = 0; i < rest.size(); ++i) {
    const std::string& a = rest[i];
    if (a.rfind("--", 0) == 0) {
      const auto spec = std::find_if(specs.begin(), specs.end(),
                                     [&](const OptionSpec& s) { return "--" + std::string(s.name) == a; });
      if (spec != specs.end() && spec->value_name) ++i;
      continue;
    }
    if (!name.empty()) throw UsageError("new: one NAME, not '" + echo(name) + "' and '" + echo(a) + "'");
    name = a;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
    --i;
  }
  auto options = parse_options("new", rest, specs);
  if (options.has("help")) {
    out << "usage: fractalis new NAME [--from ID] [--dir DIR] [--no-build]\n\n"
           "Writes a scene project NAME (NAME.c, NAME.cl, CMakeLists.txt, README.md), builds it\n"
           "against the SDK and installs it into your scene folder, where `fractalis explore`\n"
           "finds it. --from ID starts from an in-tree scene's sources (`fractalis list` names\n"
           "them). An existing folder is never written over.\n\n"
        << format_options(specs);
    return 0;
  }
  if (name.empty()) throw UsageError("new: NAME is required (fractalis new my_scene)");
  if (const std::string why = scene_id_problem(name); !why.empty())
    throw UsageError("new: '" + echo(name) + "' cannot be a scene id: " + why);

  // The id must be free: a second file declaring a scene's id is refused when loaded.
  const Settings settings = load_settings(options);
  const auto folders = plugin_folders(settings, options);
  for (const auto& o : load_plugins(folders, settings.plugins))
    if (o.scene && o.scene->info.id == name)
      throw UsageError("new: there is a scene '" + name + "' already (" + o.file.string() +
                       "); choose another name");

  const std::filesystem::path template_dir = shipped_folder(
      FRACTALIS_SDK_SOURCE_DIR "/template", FRACTALIS_TEMPLATE_INSTALL_DIR);
  const std::filesystem::path sources =
      shipped_folder(FRACTALIS_SCENE_SOURCES_SOURCE_DIR, FRACTALIS_SCENE_SOURCES_INSTALL_DIR);
  std::string error;
  std::vector<ProjectFile> files;
  const auto from = options.get("from");
  if (from) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(sources / *from / (*from + ".c"), ec)) {
      std::vector<std::string> ids;
      for (const auto& entry : std::filesystem::directory_iterator(sources, ec))
        if (std::filesystem::exists(entry.path() / (entry.path().filename().string() + ".c")))
          ids.push_back(entry.path().filename().string());
      std::sort(ids.begin(), ids.end());
      std::string list;
      for (const std::string& id : ids) list += (list.empty() ? "" : ", ") + id;
      throw UsageError("new: --from '" + echo(*from) + "' is no in-tree scene" +
                       (ids.empty() ? " (no scene sources found in " + sources.string() + ")"
                                    : "; the in-tree scenes are " + list));
    }
    files = project_from_scene(sources / *from, *from, name, template_dir, &error);
  } else {
    files = project_from_template(template_dir, name, &error);
  }
  if (files.empty()) throw std::runtime_error("new: " + error);

  std::filesystem::path dir;
  if (const auto d = options.get("dir")) {
    dir = *d;
  } else {
    const std::filesystem::path data = user_folder(UserFolder::Data);
    if (data.empty()) throw UsageError("new: no home folder to put the project in: give --dir DIR");
    dir = data / "scene-sources" / name;
  }
  if (!write_project(dir, files, &error)) throw std::runtime_error("new: " + error);
  out << "wrote the scene project '" << name << "' in " << dir.string() << ":";
  for (const ProjectFile& f : files) out << " " << f.name;
  out << "\n";
  if (options.has("no-build")) return 0;

  // Build it: CMake and a C compiler are what a scene needs.
  const std::filesystem::path cmake = find_program_on_path("cmake");
  if (cmake.empty())
    throw std::runtime_error(
        "new: the project is written, but CMake is not on the PATH, so it was not built "
        "(Debian: apt-get install cmake; then: cmake -S " + dir.string() + " -B " +
        (dir / "build").string() + " && cmake --build " + (dir / "build").string() + ")");
  if (find_program_on_path("cc").empty() && find_program_on_path("gcc").empty() &&
      find_program_on_path("clang").empty())
    throw std::runtime_error(
        "new: the project is written, but no C compiler (cc, gcc or clang) is on the PATH, so it "
        "was not built (Debian: apt-get install gcc)");
  const std::filesystem::path sdk = sdk_package_folder();
  if (sdk.empty())
    throw std::runtime_error("new: the project is written, but the scene SDK is not installed "
                             "beside this fractalis (cmake --install BUILD puts it there)");
  const std::filesystem::path build = dir / "build";
  err << "fractalis: building " << name << " in " << build.string() << "\n";
  const std::filesystem::path self = executable_path();
  if (!run(cmake,
           {"-S", dir.string(), "-B", build.string(), "-DCMAKE_BUILD_TYPE=Release",
            "-DFractalisSDK_DIR=" + sdk.string(), "-DFRACTALIS_EXECUTABLE=" + self.string()},
           &error) ||
      !run(cmake, {"--build", build.string()}, &error) ||
      !run(cmake, {"--install", build.string()}, &error))
    throw std::runtime_error("new: the project is written, but building it failed (" + error +
                             "; CMake's output is above)");
  out << "built and installed it into " << user_scene_folder().string() << "\n\n"
      << "next:\n"
      << "  fractalis explore --edit " << dir.string() << "\n"
      << "      flies it while you edit: a saved " << name
      << ".cl (the distance estimator) shows at once,\n"
      << "      a saved " << name << ".c (parameters, camera, lights) is rebuilt and reloaded\n";
  return 0;
}

}  // namespace fr
