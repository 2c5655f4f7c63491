// build_paths.hpp — where this build put its programs and scenes, for a fractalis that runs from
// the build tree (an installed one finds them from its own place instead).
//
// The values are in one source file that CMake generates (build_paths.cpp in the build folder),
// not in compile definitions: a definition holding a path of the checkout differs in every clone,
// and ccache would then compile again (or at least preprocess again) every file built with it.
#pragma once

namespace fr::build_paths {

extern const char* const plugin_dir;     // the in-tree scenes' plugins
extern const char* const paths_dir;      // the shipped camera paths (config/paths in the checkout)
extern const char* const root;           // the build folder
extern const char* const fractalis;      // the fractalis executable
extern const char* const render_worker;  // fractalis-render-worker
extern const char* const scene_host;     // fractalis-scene-host

}  // namespace fr::build_paths
