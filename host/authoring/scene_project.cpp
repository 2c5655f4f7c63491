#include "authoring/scene_project.hpp"

#include "io/atomic_file.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

namespace fr {
namespace {

bool read_text(const std::filesystem::path& file, std::string* text, std::string* error) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    *error = "cannot read " + file.string();
    return false;
  }
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

// Every occurrence of `from` in `text` replaced by `to`; how many there were.
int replace_all(std::string& text, const std::string& from, const std::string& to) {
  int count = 0;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
    ++count;
  }
  return count;
}

// `text` in double quotes, as it stands in C. (Appended: GCC 12 warns, wrongly, of overlapping
// copies in a one-character literal plus a string.)
std::string quoted(const std::string& text) {
  std::string q;
  q += '"';
  q += text;
  q += '"';
  return q;
}

// "my_blob" -> "My blob": the scene's display name until its author gives one.
std::string display_name(const std::string& id) {
  std::string name = id;
  for (char& c : name)
    if (c == '_') c = ' ';
  if (!name.empty() && name[0] >= 'a' && name[0] <= 'z') name[0] = static_cast<char>(name[0] - 32);
  return name;
}

// Replaces the value of the descriptor's `.name = "..."` with `value`; false if it has none.
bool set_string_field(std::string& c_source, const std::string& field, const std::string& value) {
  const std::string key = "." + field + " = \"";
  const size_t at = c_source.find(key);
  if (at == std::string::npos) return false;
  const size_t start = at + key.size();
  const size_t end = c_source.find('"', start);
  if (end == std::string::npos) return false;
  c_source.replace(start, end - start, value);
  return true;
}

std::string readme(const std::string& name, const std::string& from) {
  std::ostringstream out;
  out << "# " << name << " — a Fractalis scene\n\n"
      << (from.empty() ? "Made by `fractalis new " + name + "` from the SDK's template."
                       : "Made by `fractalis new " + name + " --from " + from +
                             "` from the in-tree scene `" + from + "`.")
      << "\n\n"
         "- `"
      << name
      << ".cl`: the distance estimator, `scene_de` (and the `fr/*.cl` library it includes).\n"
         "- `"
      << name
      << ".c`: the descriptor: parameters, camera, lights, description, credit, callbacks.\n\n"
         "```sh\n"
         "fractalis explore --scene "
      << name
      << "                          # fly it\n"
         "cmake --build build && cmake --install build   # rebuild after an edit\n"
         "ctest --test-dir build --output-on-failure      # fractalis check on it\n"
         "```\n\n"
         "The SDK's guide, writing-a-scene.md, says what every field means.\n";
  return out.str();
}

std::string cmake_lists(const std::filesystem::path& template_dir, const std::string& name,
                        bool with_surface, std::string* error) {
  std::string text;
  if (!read_text(template_dir / "CMakeLists.txt", &text, error)) return "";
  replace_all(text, "my_scene", name);
  if (with_surface &&
      !replace_all(text, "DE_SOURCE " + name + ".cl",
                   "DE_SOURCE " + name + ".cl\n  SURFACE_SOURCE " + name + "_surface.cl")) {
    *error = (template_dir / "CMakeLists.txt").string() + ": no DE_SOURCE line to follow";
    return "";
  }
  return text;
}

}  // namespace

std::string scene_id_problem(const std::string& name) {
  const std::string rule =
      "a scene id is lower-case letters, digits and '_', starting with a letter, at most 64";
  if (name.empty() || name.size() > 64) return rule;
  if (!(name[0] >= 'a' && name[0] <= 'z')) return rule;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return rule;
  return "";
}

std::vector<ProjectFile> project_from_template(const std::filesystem::path& template_dir,
                                               const std::string& name, std::string* error) {
  std::vector<ProjectFile> files;
  for (const char* file : {"my_scene.c", "my_scene.cl"}) {
    std::string text;
    if (!read_text(template_dir / file, &text, error)) return {};
    replace_all(text, "my_scene", name);
    std::string out_name = file;
    replace_all(out_name, "my_scene", name);
    files.push_back({out_name, text});
  }
  if (!set_string_field(files[0].text, "name", display_name(name))) {
    *error = (template_dir / "my_scene.c").string() + ": no .name field";
    return {};
  }
  const std::string lists = cmake_lists(template_dir, name, false, error);
  if (lists.empty()) return {};
  files.push_back({"CMakeLists.txt", lists});
  files.push_back({"README.md", readme(name, "")});
  return files;
}

std::vector<ProjectFile> project_from_scene(const std::filesystem::path& scene_dir,
                                            const std::string& id, const std::string& name,
                                            const std::filesystem::path& template_dir,
                                            std::string* error) {
  std::string c_source, de_source, surface_source;
  if (!read_text(scene_dir / (id + ".c"), &c_source, error) ||
      !read_text(scene_dir / (id + ".cl"), &de_source, error))
    return {};
  std::error_code ec;
  const bool with_surface = std::filesystem::exists(scene_dir / (id + "_surface.cl"), ec);
  if (with_surface && !read_text(scene_dir / (id + "_surface.cl"), &surface_source, error))
    return {};
  // The descriptor: its id, display name and the names of its sources (the .cl files are
  // embedded under the names the descriptor gives them, which compiler messages show).
  if (!set_string_field(c_source, "id", name)) {
    *error = (scene_dir / (id + ".c")).string() + ": no .id field";
    return {};
  }
  std::string old_name;
  if (const size_t at = c_source.find(".name = \""); at != std::string::npos) {
    const size_t start = at + 9;
    old_name = c_source.substr(start, c_source.find('"', start) - start);
  }
  set_string_field(c_source, "name", display_name(name) + " (from " + old_name + ")");
  replace_all(c_source, quoted(id + ".cl"), quoted(name + ".cl"));
  replace_all(c_source, quoted(id + "_surface.cl"), quoted(name + "_surface.cl"));
  replace_all(c_source, id + ".c ", name + ".c ");  // the file's opening comment
  std::vector<ProjectFile> files = {{name + ".c", c_source}, {name + ".cl", de_source}};
  if (with_surface) files.push_back({name + "_surface.cl", surface_source});
  const std::string lists = cmake_lists(template_dir, name, with_surface, error);
  if (lists.empty()) return {};
  files.push_back({"CMakeLists.txt", lists});
  files.push_back({"README.md", readme(name, id)});
  return files;
}

bool write_project(const std::filesystem::path& dir, const std::vector<ProjectFile>& files,
                   std::string* error) {
  std::error_code ec;
  if (std::filesystem::exists(std::filesystem::symlink_status(dir, ec))) {
    *error = dir.string() + " already exists: nothing was written (choose another name or --dir)";
    return false;
  }
  const std::filesystem::path parent = dir.parent_path().empty() ? "." : dir.parent_path();
  std::filesystem::create_directories(parent, ec);
  if (ec) {
    *error = "cannot make " + parent.string() + ": " + ec.message();
    return false;
  }
  std::string hidden = ".";
  hidden += dir.filename().string();
  hidden += ".new";
  const std::filesystem::path temporary = parent / hidden;
  std::filesystem::remove_all(temporary, ec);  // a leftover of an interrupted `new`
  if (!std::filesystem::create_directory(temporary, ec)) {
    *error = "cannot make " + temporary.string() + ": " + (ec ? ec.message() : "it exists");
    return false;
  }
  for (const ProjectFile& f : files) {
    if (!write_file_atomic(temporary / f.name, f.text, error)) {
      std::filesystem::remove_all(temporary, ec);
      return false;
    }
  }
  std::filesystem::rename(temporary, dir, ec);
  if (ec) {
    std::filesystem::remove_all(temporary, ec);
    *error = "cannot put the project at " + dir.string() + ": " + ec.message();
    return false;
  }
  return true;
}

}  // namespace fr
