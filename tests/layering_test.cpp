// The host's folders in floors, each including only its own headers and those of the folders
// below it (DESIGN.md: "a folder depends on the ones below it, never sideways in circles").
// The order, bottom first, is the one in docs/architecture.md (Folders and floors); an include that reaches up or
// sideways fails here with the file and line.
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fr {
namespace {

// Bottom first. A folder may include itself and any folder before it.
const std::vector<std::string> kFloors = {
    "platform",  // what differs between Linux and Windows
    "scene",     // a scene as plain data
    "io",        // files, text, processes: no fractalis types
    "mpi",       // the ranks of an MPI job and the tasks they share
    "plugin",    // plugin files and code, the scene-host process
    "render",    // OpenCL, kernels, the renderer, its settings
    "worker",    // the render worker process that runs scene kernels
    "settings",  // the settings file over RenderSettings and the rest
    "image",     // PNG, OpenEXR, posters
    "video",     // the FFmpeg encoder
    "path",      // camera paths, presets
    "import",    // other tools' files as presets (Mandelbulber2's .fract)
    "animate",   // frame plans, PNG sequences
    "bench",     // frame timing and reports
    "sweep",     // error against run time
    "check",     // the conformance checks
    "authoring", // scene projects: `fractalis new`
    "app",       // the explorer core, the scene library, the explorer benchmark (drivers)
    "ui",        // the SDL window and the overlay
    "cli",       // the commands
};

TEST(Layering, NoFolderIncludesOneAboveIt) {
  const std::filesystem::path host = std::filesystem::path(SOURCE_DIR) / "host";
  size_t files = 0, includes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(host)) {
    const auto& path = entry.path();
    if (!entry.is_regular_file() || (path.extension() != ".cpp" && path.extension() != ".hpp"))
      continue;
    const std::string folder = path.parent_path() == host
                                   ? "main"  // main.cpp, scene_host_main.cpp: above everything
                                   : path.parent_path().filename().string();
    const auto own = std::find(kFloors.begin(), kFloors.end(), folder);
    if (folder != "main") {
      ASSERT_NE(own, kFloors.end()) << "host/" << folder << "/ has no floor in this test";
    }
    ++files;
    std::ifstream in(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const size_t hash = line.find_first_not_of(" \t");
      if (hash == std::string::npos || line.compare(hash, 10, "#include \"") != 0) continue;
      const size_t start = hash + 10, slash = line.find('/', start);
      if (slash == std::string::npos) continue;
      const std::string target = line.substr(start, slash - start);
      const auto floor = std::find(kFloors.begin(), kFloors.end(), target);
      if (floor == kFloors.end()) continue;  // not a host folder (fractalis/, the SDK's)
      ++includes;
      if (folder != "main" && floor > own)
        ADD_FAILURE() << std::filesystem::relative(path, SOURCE_DIR).string() << ":" << number
                      << ": host/" << folder << "/ includes " << target
                      << "/, which is above it (or beside it)";
    }
  }
  EXPECT_GT(files, 100u);
  EXPECT_GT(includes, 300u);
}

// What differs between Linux and Windows lives in host/platform/ (its README): no other file of
// the host, the scenes or the SDK's sources asks which system it is built for, and the platform
// layer picks its implementation by file (NAME_posix.cpp, NAME_windows.cpp), not by #ifdef.
TEST(Layering, OnlyThePlatformLayerKnowsTheSystem) {
  const std::filesystem::path root(SOURCE_DIR);
  size_t files = 0;
  for (const char* tree : {"host", "plugins"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / tree)) {
      const auto& path = entry.path();
      if (!entry.is_regular_file() || (path.extension() != ".cpp" && path.extension() != ".hpp" &&
                                       path.extension() != ".c" && path.extension() != ".h"))
        continue;
      ++files;
      const bool platform = path.parent_path().filename() == "platform";
      const std::string stem = path.stem().string();
      if (!platform && (stem.ends_with("_posix") || stem.ends_with("_windows")))
        ADD_FAILURE() << std::filesystem::relative(path, root).string()
                      << ": a per-system file outside host/platform/";
      std::ifstream in(path);
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        const size_t hash = line.find_first_not_of(" \t");
        if (hash == std::string::npos || line[hash] != '#') continue;
        for (const char* system : {"_WIN32", "_WIN64", "__linux__", "__MINGW", "_MSC_VER"})
          if (line.find(system) != std::string::npos)
            ADD_FAILURE() << std::filesystem::relative(path, root).string() << ":" << number
                          << ": asks for " << system << " (" << line << ")";
      }
    }
  }
  EXPECT_GT(files, 100u);
}

}  // namespace
}  // namespace fr
