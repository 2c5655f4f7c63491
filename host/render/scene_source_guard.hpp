// scene_source_guard.hpp — a scene's OpenCL source may not reach into the host's kernel code.
//
// A scene's DE and surface sources are pasted between the host's prelude and the host's render
// stages (kernel_assembly.cpp), so a macro they define would silently rewrite every host line
// after them (`#define fmax(a, b) (a)` breaks the march), and a comment, `#if` or brace they leave
// open swallows it. The assembler therefore refuses, naming the file and line:
//   - `#define` or `#undef` of a name the host's kernel code defines (macro, function or type), or
//     of a name beginning with FR_ or fr_ (reserved: the host's switches and hooks);
//   - a function definition whose name a host stage after the scene defines;
//   - a block comment, `#if`, `(` or `{` still open at the end of the file;
// and the assembler saves every macro the scene defines or undefines before the scene's code and
// restores it after (#pragma push_macro / pop_macro), so the scene's own macros end where its
// code ends, even those named like the OpenCL implementation's built-ins.
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fr {

// What the host's kernel files define, by kind.
struct HostKernelNames {
  std::set<std::string> defined;          // macros, functions and types anywhere in kernels/
  std::set<std::string> functions_after;  // functions of the files pasted after the scene
};

// Collects the names `before` (prelude, library) and `after` (stages) define.
HostKernelNames collect_host_names(const std::vector<std::string_view>& before,
                                   const std::vector<std::string_view>& after);

// Checks one scene source file (`file_name` as its author named it) and returns the macros it
// defines or undefines. Throws KernelBuildError "scene 'ID': FILE:LINE: ..." for what the header
// lists.
std::vector<std::string> guard_scene_source(const std::string& scene_id, std::string_view file_name,
                                            std::string_view text, const HostKernelNames& host);

// Whether the source defines a function of this name at file scope (kernel_assembly.cpp: a
// surface source's optional scene_material).
bool source_defines_function(std::string_view text, std::string_view name);

}  // namespace fr
