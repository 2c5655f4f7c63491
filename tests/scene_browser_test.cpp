// The scene browser without a window: its search, its selection, the thumbnails' cache key
// (every input it depends on changes it; nothing else does), and the thumbnail cache against
// hostile files — a corrupt or truncated PNG, a picture of the wrong size, a header that asks
// for gigabytes, a folder that cannot be written — each said once, nothing lost, nothing shown
// wrong. (Under Xvfb, explorer_window_test drives the browser as a user does.)
#include "app/scene_browser.hpp"
#include "image/png_write.hpp"
#include "plugin/scene_instance.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace fr {
namespace {

TEST(SceneBrowserSearch, EveryWordMustOccurCaseIgnored) {
  const std::string text = "mandelbox box classic tom lowe's amazing box fold";
  EXPECT_TRUE(browser_matches(text, ""));
  EXPECT_TRUE(browser_matches(text, "   "));
  EXPECT_TRUE(browser_matches(text, "BOX"));
  EXPECT_TRUE(browser_matches(text, "lowe  fold"));
  EXPECT_TRUE(browser_matches(text, "mandel"));
  EXPECT_FALSE(browser_matches(text, "box julia")) << "every word, not any";
  EXPECT_FALSE(browser_matches(text, "kleinian"));
}

RgbaImage gradient(int w, int h) {
  RgbaImage image{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (size_t i = 0; i < image.rgba8.size(); ++i) image.rgba8[i] = static_cast<uint8_t>(i * 7);
  return image;
}

TEST(ThumbnailKey, FollowsEveryInputAndNothingElse) {
  const auto scene = test::mandelbulb();
  const SceneInfo& info = scene->info;
  const SceneState state = make_default_state(info);
  RenderSettings settings;
  settings.width_px = 192;
  settings.height_px = 108;
  const std::string key = thumbnail_key(info, state, settings);
  ASSERT_EQ(key.size(), 16u);
  EXPECT_EQ(thumbnail_key(info, make_default_state(info), settings), key) << "stable";

  SceneState other = state;
  const int power = info.find_param("power");
  ASSERT_GE(power, 0);
  other.params[power].v[0] += 1;
  EXPECT_NE(thumbnail_key(info, other, settings), key) << "a parameter value";
  other = state;
  other.camera.eye[0] += 0.5;
  EXPECT_NE(thumbnail_key(info, other, settings), key) << "the camera";
  other = state;
  other.bounding_radius *= 2;
  EXPECT_NE(thumbnail_key(info, other, settings), key) << "the bounding radius";
  if (!state.lights.empty()) {
    other = state;
    other.lights[0].intensity *= 2;
    EXPECT_NE(thumbnail_key(info, other, settings), key) << "a light";
  }
  RenderSettings s = settings;
  s.exposure = 2;
  EXPECT_NE(thumbnail_key(info, state, s), key) << "a render setting";
  s = settings;
  s.width_px = 96;
  EXPECT_NE(thumbnail_key(info, state, s), key) << "the size";
  SceneInfo changed = info;
  changed.de_source += "\n// a comment changes the scene's content\n";
  EXPECT_NE(thumbnail_key(changed, state, settings), key) << "the DE's source";
  // The scene's time and frame number do not change its default picture.
  other = state;
  other.time_s = 5;
  other.frame_index = 9;
  EXPECT_EQ(thumbnail_key(info, other, settings), key);
}

TEST(ThumbnailCache, StoresAndLoadsThePixelsExactly) {
  const auto dir = test::fresh_dir("thumbnail_cache_round_trip");
  ThumbnailCache cache(dir / "thumbs");
  const RgbaImage image = gradient(24, 13);
  EXPECT_FALSE(cache.load("00112233aabbccdd", 24, 13).has_value()) << "nothing stored yet";
  cache.store("00112233aabbccdd", image);
  EXPECT_TRUE(cache.problems().empty());
  const auto back = ThumbnailCache(dir / "thumbs").load("00112233aabbccdd", 24, 13);
  ASSERT_TRUE(back.has_value()) << "a second cache on the folder (a second start) finds it";
  EXPECT_EQ(back->rgba8, image.rgba8);
  // A key that is not ours is never a path.
  EXPECT_FALSE(cache.load("../../etc/passwd", 24, 13).has_value());
  EXPECT_FALSE(cache.load("", 24, 13).has_value());
}

TEST(ThumbnailCache, ABadFileIsSaidRemovedAndNotShown) {
  const auto dir = test::fresh_dir("thumbnail_cache_hostile") / "thumbs";
  std::filesystem::create_directories(dir);
  ThumbnailCache cache(dir);
  const auto write = [&](const std::string& key, const std::string& bytes) {
    std::ofstream(dir / (key + ".png"), std::ios::binary) << bytes;
  };
  // Not a PNG at all.
  write("0000000000000001", "this is not a picture");
  // A real PNG cut in half.
  const RgbaImage image = gradient(24, 13);
  std::string error;
  ASSERT_TRUE(write_png_atomic(dir / "whole.png", 24, 13, image.rgba8, &error)) << error;
  const std::string whole = test::read_file(dir / "whole.png");
  write("0000000000000002", whole.substr(0, whole.size() / 2));
  // A whole PNG of another size than its key was made for.
  write("0000000000000003", whole);
  // A PNG header that says 100000 x 100000 pixels (40 GB of RGBA): refused before reading.
  std::string huge = whole;
  const unsigned char side[4] = {0x00, 0x01, 0x86, 0xa0};  // 100000, big-endian, at IHDR
  for (int i = 0; i < 4; ++i) huge[16 + i] = huge[20 + i] = static_cast<char>(side[i]);
  // IHDR's CRC (over its type and 13 data bytes) made right, so only the size is wrong.
  uint32_t crc = 0xffffffffu;
  for (int i = 12; i < 29; ++i) {
    crc ^= static_cast<unsigned char>(huge[i]);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xffffffffu;
  for (int i = 0; i < 4; ++i) huge[29 + i] = static_cast<char>(crc >> (24 - 8 * i));
  write("0000000000000004", huge);

  for (const char* key : {"0000000000000001", "0000000000000002", "0000000000000004"})
    EXPECT_FALSE(cache.load(key, 24, 13).has_value()) << key;
  EXPECT_FALSE(cache.load("0000000000000003", 48, 26).has_value()) << "the wrong size";
  ASSERT_EQ(cache.problems().size(), 4u);
  for (const char* key : {"0000000000000001", "0000000000000002", "0000000000000003",
                          "0000000000000004"}) {
    EXPECT_FALSE(std::filesystem::exists(dir / (std::string(key) + ".png")))
        << key << ": removed, so it is rendered again";
    bool named = false;
    for (const std::string& p : cache.problems()) named = named || p.find(key) != std::string::npos;
    EXPECT_TRUE(named) << key << " is named in a problem";
  }
  EXPECT_NE(cache.problems()[0].find("not a readable PNG"), std::string::npos)
      << cache.problems()[0];
  EXPECT_NE(cache.problems()[2].find("100000x100000"), std::string::npos) << cache.problems()[2];
  EXPECT_NE(cache.problems()[3].find("not the 48x26"), std::string::npos) << cache.problems()[3];
  EXPECT_TRUE(std::filesystem::exists(dir / "whole.png")) << "other files are left alone";
}

TEST(ThumbnailCache, AnUnwritableFolderIsSaidOnceAndNothingElseFails) {
  const auto dir = test::fresh_dir("thumbnail_cache_unwritable");
  // A file where the folder should be: no user (root included) can make the folder.
  std::ofstream(dir / "blocked") << "a file, not a folder";
  ThumbnailCache cache(dir / "blocked" / "thumbs");
  const RgbaImage image = gradient(8, 8);
  cache.store("00000000000000aa", image);
  cache.store("00000000000000bb", image);
  ASSERT_EQ(cache.problems().size(), 1u) << "said once, not for every picture";
  EXPECT_NE(cache.problems()[0].find("blocked"), std::string::npos) << cache.problems()[0];
  EXPECT_NE(cache.problems()[0].find("in memory only"), std::string::npos) << cache.problems()[0];
  EXPECT_FALSE(cache.load("00000000000000aa", 8, 8).has_value());
  EXPECT_EQ(test::read_file(dir / "blocked"), "a file, not a folder") << "nothing overwritten";
  // No folder at all: no disk cache, and no problem to say.
  ThumbnailCache none{std::filesystem::path()};
  none.store("00000000000000aa", image);
  EXPECT_TRUE(none.problems().empty());
  EXPECT_FALSE(none.load("00000000000000aa", 8, 8).has_value());
}

}  // namespace
}  // namespace fr
