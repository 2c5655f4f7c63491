// A scene's source may not reach into the host's kernel code (render/scene_source_guard.hpp):
// each way of doing so is refused with the file and line, and what is allowed stays allowed.
#include "render/scene_source_guard.hpp"
#include "render/cl_runtime.hpp"
#include "render/kernel_assembly.hpp"

#include <gtest/gtest.h>

namespace fr {
namespace {

SceneInfo scene_with(const std::string& de_source, const std::string& surface_source = "") {
  SceneInfo info;
  info.id = "guarded";
  info.de_source_name = "guarded.cl";
  info.de_source = de_source;
  info.surface_source_name = "guarded_surface.cl";
  info.surface_source = surface_source;
  info.bounding_radius = 2;
  return info;
}

const std::string kDe =
    "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
    "  return v3_length(p) - to_real(1);\n}\n";

// The error assembling `info` gives, or "" when it assembles.
std::string refusal(const SceneInfo& info) {
  try {
    assemble_render_kernel(info, {}, KernelConfig{});
    assemble_probe_kernel(info, {}, KernelConfig{});
  } catch (const KernelBuildError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneSourceGuard, HostNamesAreKnown) {
  // From the real kernels/: the prelude's helpers and types, the DE library, the stages.
  const HostKernelNames host = collect_host_names(
      {"#define lane_select(m, a, b) x\ntypedef float real_t;\ntypedef struct fr_s { int a; } "
       "fr_s_t;\ninline real_t v3_length(int v) { return 0; }\n"},
      {"march_result_t march(ray_t r) {\n  if (x) { y(); }\n}\nint declared_only(int a);\n"});
  for (const char* name : {"lane_select", "real_t", "fr_s", "fr_s_t", "v3_length", "march"})
    EXPECT_TRUE(host.defined.count(name)) << name;
  EXPECT_TRUE(host.functions_after.count("march"));
  EXPECT_FALSE(host.functions_after.count("v3_length")) << "before the scene, not after";
  EXPECT_FALSE(host.defined.count("declared_only")) << "a prototype defines nothing";
  EXPECT_FALSE(host.defined.count("y")) << "a call inside a body defines nothing";
}

TEST(SceneSourceGuard, ReachingIntoTheHostIsRefusedWithFileAndLine) {
  struct Case {
    std::string source, expected;
  };
  const std::vector<Case> cases = {
      {"#define fmax_hack 1\n#define v3_length(v) to_real(0)\n" + kDe,
       "guarded.cl:2: `#define v3_length` would change the host's own v3_length"},
      {"\n\n#undef lane_select\n" + kDe, "guarded.cl:3: `#undef lane_select`"},
      {"  #  define   real_t double\n" + kDe, "guarded.cl:1: `#define real_t`"},
      {"#define FR_APPLY_LENS(x) x\n" + kDe,
       "guarded.cl:1: `#define FR_APPLY_LENS`: names beginning FR_ or fr_ are the host's"},
      {"#define fr_mine 2\n" + kDe, "guarded.cl:1: `#define fr_mine`: names beginning FR_"},
      {"#define PARAM(k) 0\n" + kDe, "guarded.cl:1: `#define PARAM`"},
      {kDe + "real_t march(real_t x) { return x; }\n",
       "guarded.cl:4: function march() has the name of one of the host's render stages"},
      {kDe + "/* a note\n that never ends\n",
       "guarded.cl:4: a comment opened here is never "
       "closed"},
      {"#if 1\n" + kDe, "guarded.cl:1: this #if has no #endif in the file"},
      {kDe + "#ifdef X\n#if 0\n#endif\n", "guarded.cl:4: this #if has no #endif"},
      {kDe + "#endif\n", "guarded.cl:4: #endif without #if"},
      {kDe + "real_t helper(real_t x) {\n  return x;\n",
       "guarded.cl:4: a '{' opened here is "
       "never closed"},
      {kDe + "int table[] = (1, 2\n", "guarded.cl:4: a '(' opened here is never closed"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.source);
    const std::string said = refusal(scene_with(c.source));
    EXPECT_NE(said.find("scene 'guarded': " + c.expected), std::string::npos) << said;
  }
  // The surface source is the scene's too.
  const std::string said = refusal(scene_with(kDe, "\n#define v3_dot(a, b) 0\n"));
  EXPECT_NE(said.find("guarded_surface.cl:2: `#define v3_dot`"), std::string::npos) << said;
}

TEST(SceneSourceGuard, WhatIsAllowedStaysAllowed) {
  for (const std::string& source : {
           // the scene's own macros, redefined and undefined by itself, with continuations
           "#define ITERATIONS 8\n#define TWICE(x) \\\n  ((x) + (x))\n#undef ITERATIONS\n"
           "#define ITERATIONS 9\n" +
               kDe,
           // host names inside comments, strings and character literals
           "/* #define v3_length 0 and { ( */\n// #undef lane_select {\n" + kDe +
               "constant char note[] = \"#define real_t { (\";\nconstant char brace = '{';\n",
           // braces and parentheses inside macro bodies, a directive with a comment after it
           "#define OPEN_BLOCK {\n#define CALL(f) f(\n#define N 3 /* three\n lines */\n" + kDe,
           // balanced conditionals, a scene's own helper called like a stage but not defined
           "#if FR_DE_LIBRARY_VERSION >= 10000\n#ifdef SOMETHING\n#endif\n#else\n#endif\n" + kDe,
           // the scene's entry point renamed and wrapped (as tests/CMakeLists.txt's fixtures do)
           "#define scene_de inner_de\n" + kDe +
               "#undef scene_de\n"
               "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
               "  return inner_de(p, params);\n}\n",
       }) {
    SCOPED_TRACE(source);
    EXPECT_EQ(refusal(scene_with(source)), "");
  }
}

TEST(SceneSourceGuard, SceneMacrosAreRestoredAfterTheScene) {
  const std::string source =
      kDe + "#define fmax(a, b) (a)\n#define HELPER 1\n#undef HELPER\n#define HELPER 2\n";
  const AssembledKernel k = assemble_render_kernel(scene_with(source), {}, KernelConfig{});
  const size_t push_fmax = k.source.find("#pragma push_macro(\"fmax\")\n");
  const size_t scene_at = k.source.find("#define fmax(a, b) (a)");
  const size_t pop_fmax = k.source.find("#pragma pop_macro(\"fmax\")\n");
  const size_t pop_helper = k.source.find("#pragma pop_macro(\"HELPER\")\n");
  const size_t march_at = k.source.find("#line 1 \"march.cl\"");
  ASSERT_NE(push_fmax, std::string::npos);
  ASSERT_NE(pop_fmax, std::string::npos);
  ASSERT_NE(pop_helper, std::string::npos);
  EXPECT_LT(push_fmax, scene_at);
  EXPECT_LT(scene_at, pop_fmax);
  EXPECT_LT(pop_fmax, march_at) << "before the host's stages";
  EXPECT_EQ(k.source.find("#pragma pop_macro(\"HELPER\")\n", pop_helper + 1), std::string::npos)
      << "once, however often the scene defined it";
}

}  // namespace
}  // namespace fr
