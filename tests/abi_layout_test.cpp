// The scene ABI's layout is frozen: these sizes and offsets are ABI 1.0 on LP64 systems. A change
// here breaks every plugin ever built; structs may only grow at the end with a minor bump.
// This file is compiled as C++20 with -pedantic -Werror; abi_layout_c11.c is the C11 side.
#include <fractalis/fractalis.h>

#include <gtest/gtest.h>

#include <cstddef>

extern "C" size_t fr_test_c_layout(int what);

static_assert(sizeof(void*) == 8, "the frozen layout below is for LP64");
// ABI 1.1 grew three structs at their ends; every 1.0 offset below is unchanged (a 1.0 plugin's
// struct is the 1.1 struct's prefix, which is what struct_size and FR_STRUCT_HAS rely on).
static_assert(sizeof(fr_scene_entry) == 48);
static_assert(offsetof(fr_scene_entry, init) == 24);
static_assert(offsetof(fr_scene_entry, deinit) == 32);
static_assert(offsetof(fr_scene_entry, get_extension) == 40);
static_assert(offsetof(fr_scene_entry, abi_major) == 0);
static_assert(offsetof(fr_scene_entry, abi_minor) == 4);
static_assert(offsetof(fr_scene_entry, struct_size) == 8);
static_assert(offsetof(fr_scene_entry, scene) == 16);

static_assert(sizeof(fr_value) == 24);
// 1.0 ended at 120; 1.2 added choices and choice_count; 1.4 detail_ratio.
static_assert(sizeof(fr_param_desc) == 144);
static_assert(offsetof(fr_param_desc, detail_ratio) == 136);
static_assert(offsetof(fr_param_desc, choices) == 120);
static_assert(offsetof(fr_param_desc, choice_count) == 128);
static_assert(offsetof(fr_param_desc, key) == 16);
static_assert(offsetof(fr_param_desc, default_value) == 48);
static_assert(offsetof(fr_param_desc, max_value) == 96);

static_assert(sizeof(fr_camera) == 88);
static_assert(offsetof(fr_camera, eye) == 8);
static_assert(offsetof(fr_camera, fov_deg) == 80);
static_assert(sizeof(fr_light) == 88);
static_assert(offsetof(fr_light, falloff) == 72);
static_assert(offsetof(fr_light, radius) == 80);  // ABI 1.3

static_assert(sizeof(fr_host) == 48);
static_assert(offsetof(fr_host, host_name) == 24);
static_assert(offsetof(fr_host, get_extension) == 40);
static_assert(sizeof(fr_thread_log) == 16);
static_assert(offsetof(fr_host, log) == 16);

static_assert(sizeof(fr_frame_state) == 80);
static_assert(offsetof(fr_frame_state, light_stride) == 72);
static_assert(offsetof(fr_frame_state, params) == 32);
static_assert(offsetof(fr_frame_state, bounding_radius) == 64);

// 1.0 ended at 160; 1.2 added tags and credit.
static_assert(sizeof(fr_scene_desc) == 176);
static_assert(offsetof(fr_scene_desc, tags) == 160);
static_assert(offsetof(fr_scene_desc, credit) == 168);
static_assert(offsetof(fr_scene_desc, id) == 8);
static_assert(offsetof(fr_scene_desc, de_source) == 56);
static_assert(offsetof(fr_scene_desc, surface_source) == 72);
static_assert(offsetof(fr_scene_desc, params) == 88);
static_assert(offsetof(fr_scene_desc, param_count) == 96);
static_assert(offsetof(fr_scene_desc, features) == 104);
static_assert(offsetof(fr_scene_desc, bounding_radius) == 128);
static_assert(offsetof(fr_scene_desc, create) == 136);
static_assert(offsetof(fr_scene_desc, update) == 152);

TEST(AbiLayout, CAndCppAgree) {
  const size_t cpp[] = {sizeof(fr_scene_entry),
                        sizeof(fr_scene_desc),
                        sizeof(fr_param_desc),
                        sizeof(fr_camera),
                        sizeof(fr_light),
                        sizeof(fr_frame_state),
                        sizeof(fr_host),
                        sizeof(fr_value),
                        offsetof(fr_scene_desc, de_source),
                        offsetof(fr_scene_desc, features),
                        offsetof(fr_scene_desc, bounding_radius),
                        offsetof(fr_scene_desc, update),
                        offsetof(fr_param_desc, default_value),
                        offsetof(fr_frame_state, params),
                        offsetof(fr_frame_state, bounding_radius),
                        offsetof(fr_scene_entry, scene)};
  for (int i = 0; i < static_cast<int>(std::size(cpp)); ++i)
    EXPECT_EQ(fr_test_c_layout(i), cpp[i]) << "layout item " << i;
}

TEST(AbiLayout, VersionMacros) {
  EXPECT_EQ(FR_ABI_VERSION_MAJOR, 1u);
  EXPECT_EQ(FR_ABI_VERSION_MINOR, 4u);
  EXPECT_STREQ(FR_SCENE_ENTRY_SYMBOL, "fractalis_scene_entry");
}
