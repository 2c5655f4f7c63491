// fuzz_targets.hpp — the inputs fractalis takes from people and from plugins, as fuzz targets.
//
// Each target takes arbitrary bytes and must neither crash nor hang nor leak on any of them;
// wrong input is fine as long as it is refused. They are built two ways:
//   - as libFuzzer programs (fuzz/CMakeLists.txt, with clang and -DFRACTALIS_FUZZ=ON), which
//     .ci/run runs for a bounded time each;
//   - into tests/fuzz_replay_test.cpp, which feeds every file of fuzz/corpus/<target>/ and
//     fuzz/regressions/<target>/ through them in every build, the sanitizer build included.
// An input that ever crashed a target goes into fuzz/regressions/<target>/ (see fuzz/README.md).
#pragma once

#include <cstddef>
#include <cstdint>

namespace fr {

// A settings file's text (settings/settings.hpp: parsing, nesting guard, every key's checks).
int fuzz_settings_file(const uint8_t* data, size_t size);
// One --set KEY=VALUE.
int fuzz_set_override(const uint8_t* data, size_t size);
// A command line: NUL-separated arguments after a command chosen by the first byte, run through
// the CLI up to its option checks (the command then only prints its help), and each argument
// through the value parsers (sizes, vectors, numbers).
int fuzz_command_line(const uint8_t* data, size_t size);
// What a scene-host process sends for a scene's descriptor (plugin/scene_wire.hpp), decoded and
// checked as the host does (plugin/scene_checks.hpp): the host trusts no byte of it.
int fuzz_scene_descriptor(const uint8_t* data, size_t size);

// A camera path file (path/camera_path.hpp) for a scene with a parameter of each type, parsed,
// checked and, when it is a path, sampled across its length.
int fuzz_camera_path(const uint8_t* data, size_t size);
// A plugin's entry and descriptor as it lies in the plugin's memory (counts, sizes, strings,
// parameter tables, camera, lights, all from the bytes), read by the loader's copy_descriptor
// (plugin/descriptor_copy.hpp), the only code that reads plugin memory.
int fuzz_scene_desc_copy(const uint8_t* data, size_t size);

// A Mandelbulber2 settings file (import/fract_file.hpp), read and imported as a preset
// (import/mb2_import.hpp): refused with a FractError or notes, never a crash.
int fuzz_fract_file(const uint8_t* data, size_t size);

struct FuzzTarget {
  const char* name;  // its folder under fuzz/corpus and fuzz/regressions
  int (*run)(const uint8_t* data, size_t size);
};
inline constexpr FuzzTarget kFuzzTargets[] = {
    {"settings_file", fuzz_settings_file},     {"set_override", fuzz_set_override},
    {"command_line", fuzz_command_line},       {"scene_descriptor", fuzz_scene_descriptor},
    {"scene_desc_copy", fuzz_scene_desc_copy}, {"camera_path", fuzz_camera_path},
    {"fract_file", fuzz_fract_file},
};

}  // namespace fr
