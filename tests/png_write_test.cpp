// PNG output is atomic: the file appears whole or not at all, and a failed write keeps the old one.
#include "image/png_write.hpp"
#include "test_support.hpp"

#include <stb_image.h>

#include <fstream>
#include <sstream>

namespace fr {
namespace {

TEST(PngWrite, RoundTrip) {
  const auto dir = test::fresh_dir("png_roundtrip");
  std::vector<uint8_t> rgba(3 * 2 * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<uint8_t>(i * 10);
  std::string error;
  ASSERT_TRUE(write_png_atomic(dir / "a.png", 3, 2, rgba, &error)) << error;
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load((dir / "a.png").string().c_str(), &w, &h, &n, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(std::vector<uint8_t>(pixels, pixels + rgba.size()), rgba);
  stbi_image_free(pixels);
  // Nothing but the file itself is left in the folder.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(PngWrite, FailureKeepsExistingFile) {
  const auto dir = test::fresh_dir("png_failure");
  std::ofstream(dir / "keep.png") << "precious";
  std::string error;
  // Pixels that do not match the size: refused before anything is written.
  EXPECT_FALSE(write_png_atomic(dir / "keep.png", 4, 4, std::vector<uint8_t>(10), &error));
  EXPECT_NE(error.find("keep.png"), std::string::npos);
  EXPECT_EQ(test::read_file(dir / "keep.png"), "precious");
  // A folder that does not exist: a clear error naming the path.
  EXPECT_FALSE(write_png_atomic(dir / "missing" / "x.png", 1, 1, std::vector<uint8_t>(4), &error));
  EXPECT_NE(error.find("missing"), std::string::npos) << error;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

}  // namespace
}  // namespace fr
