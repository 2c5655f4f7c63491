// test_paths.hpp — the build's folders and programs that the tests use, by the names the tests
// have always used (SCENE_PLUGIN_DIR, ...), each a `const char*`.
//
// Not compile definitions: a definition holding a path of the checkout differs in every clone,
// and ccache would then compile every test again in a fresh clone (CI's case). The values are in
// one source file CMake generates (tests/test_paths.cpp in the build folder), and the host's own
// in build_paths.cpp (io/build_paths.hpp).
#pragma once

#include "io/build_paths.hpp"

namespace fr::test_paths {

extern const char* const fixture_plugin_dir;       // fixtures/plugins, built
extern const char* const test_scene_dir;           // the test scenes (unit_ball, ...)
extern const char* const test_output_dir;          // where tests write
extern const char* const source_dir;               // the checkout
extern const char* const reload_plugin_dir;        // hot reload's fixtures
extern const char* const hostile_plugin_dir;       // plugins that attack the host
extern const char* const kernel_plugin_dir;        // plugins whose OpenCL attacks the worker
extern const char* const check_plugin_dir;         // faults only `check` looks for
extern const char* const overestimate_plugin_dir;  // in-tree scenes with a scaled-up DE
extern const char* const compat_plugin_dir;        // scenes built against older ABI headers
extern const char* const ported_fixture_dir;       // the fixtures the Windows tests share
extern const char* const missing_dep_lib_dir;      // the library a fixture needs, not installed

}  // namespace fr::test_paths

#define FIXTURE_PLUGIN_DIR (::fr::test_paths::fixture_plugin_dir)
#define TEST_SCENE_DIR (::fr::test_paths::test_scene_dir)
#define TEST_OUTPUT_DIR (::fr::test_paths::test_output_dir)
#define SOURCE_DIR (::fr::test_paths::source_dir)
#define RELOAD_PLUGIN_DIR (::fr::test_paths::reload_plugin_dir)
#define HOSTILE_PLUGIN_DIR (::fr::test_paths::hostile_plugin_dir)
#define KERNEL_PLUGIN_DIR (::fr::test_paths::kernel_plugin_dir)
#define CHECK_PLUGIN_DIR (::fr::test_paths::check_plugin_dir)
#define OVERESTIMATE_PLUGIN_DIR (::fr::test_paths::overestimate_plugin_dir)
#define COMPAT_PLUGIN_DIR (::fr::test_paths::compat_plugin_dir)
#define PORTED_FIXTURE_DIR (::fr::test_paths::ported_fixture_dir)
#define MISSING_DEP_LIB_DIR (::fr::test_paths::missing_dep_lib_dir)
#define SCENE_PLUGIN_DIR (::fr::build_paths::plugin_dir)
#define FRACTALIS_EXECUTABLE (::fr::build_paths::fractalis)
