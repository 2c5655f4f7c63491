// scene_project.hpp — the files of a new scene project, as `fractalis new` writes them: from the
// SDK's template (a rippled sphere), or from the sources of an in-tree scene (`--from ID`), as
// Fragmentarium's users start from an example. Plain text in, plain text out: command_new.cpp
// finds the sources, writes the files and builds them.
//
// A project is NAME.c (the descriptor), NAME.cl (the distance estimator), NAME_surface.cl for a
// scene that colours its own surface, CMakeLists.txt (the template's, against the installed SDK)
// and README.md (what to edit next).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct ProjectFile {
  std::string name;  // a file name, no folder
  std::string text;
};

// Why `name` cannot be a scene's id (the ABI's rule: [a-z][a-z0-9_]*, 1 to 64 characters), or
// "" when it can.
std::string scene_id_problem(const std::string& name);

// The project NAME from the SDK template folder (my_scene.c, my_scene.cl, CMakeLists.txt,
// README.md). On failure (a file missing or unreadable) returns {} and sets *error.
std::vector<ProjectFile> project_from_template(const std::filesystem::path& template_dir,
                                               const std::string& name, std::string* error);

// The project NAME from the in-tree scene `id`'s folder (ID.c, ID.cl and ID_surface.cl when it
// has one), with the template's CMakeLists.txt and README.md. The C file's id, name and source
// file names become NAME's; the OpenCL is copied as it is (its `fr/...` includes are the host's
// library).
std::vector<ProjectFile> project_from_scene(const std::filesystem::path& scene_dir,
                                            const std::string& id, const std::string& name,
                                            const std::filesystem::path& template_dir,
                                            std::string* error);

// Writes `files` into `dir`, which must not exist (nothing is ever overwritten): into a
// temporary folder beside it first, renamed to `dir` at the end, so a failure leaves nothing
// half-written. False with *error naming the path and why.
bool write_project(const std::filesystem::path& dir, const std::vector<ProjectFile>& files,
                   std::string* error);

}  // namespace fr
