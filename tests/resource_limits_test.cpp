// Resources: image sizes checked against the device's and the process's memory before any work,
// and the compiled-kernel cache kept in its folder, bounded, least recently used first.
#include "render/kernel_cache.hpp"
#include "render/memory_budget.hpp"
#include "test_support.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <ctime>
#include <fstream>
#include <sstream>

namespace fr {
namespace {

// The bytes per pixel, counted by hand from renderer.cpp's buffers and FrameImage.
TEST(ResourceLimits, MemoryNeedCountsEveryBuffer) {
  const MemoryNeed display = render_memory_need(100, 50, false);
  EXPECT_EQ(display.largest_buffer_bytes, 5000u * 16);  // float4 HDR
  // HDR 16, depth 4, steps 4, AO+shadow 8, status 1, normal 12, albedo 12, RGBA8 4.
  EXPECT_EQ(display.device_bytes, 5000u * 61);
  // RGBA8 4, steps 4, status 1; PNG filter copy, stream and our copy 12.
  EXPECT_EQ(display.host_bytes, 5000u * 21);
  // Every pass also reads back linear RGBA 16, depth 4, factors 8, normal 12, albedo 12, AO 4,
  // shadow 4.
  EXPECT_EQ(render_memory_need(100, 50, true).host_bytes, 5000u * (21 + 60));
}

TEST(ResourceLimits, DeviceLimitsAreNamed) {
  DeviceInfo gpu;
  gpu.type = CL_DEVICE_TYPE_GPU;  // its buffers are not this process's memory
  gpu.max_alloc_bytes = 1ull << 30;
  gpu.global_mem_bytes = 8ull << 30;
  const std::string alloc = memory_problem(render_memory_need(9000, 9000, false), gpu);
  EXPECT_NE(alloc.find("needs 1.2 GiB for the HDR image"), std::string::npos) << alloc;
  EXPECT_NE(alloc.find("(CL_DEVICE_MAX_MEM_ALLOC_SIZE) of 1.0 GiB"), std::string::npos) << alloc;
  gpu.max_alloc_bytes = 4ull << 30;
  gpu.global_mem_bytes = 1ull << 30;
  const std::string global = memory_problem(render_memory_need(5000, 5000, false), gpu);
  EXPECT_NE(global.find("(CL_DEVICE_GLOBAL_MEM_SIZE) of 1.0 GiB"), std::string::npos) << global;
  gpu.global_mem_bytes = 8ull << 30;
  EXPECT_EQ(memory_problem(render_memory_need(640, 360, true), gpu), "");
}

#ifndef FRACTALIS_TEST_SANITIZED  // ASan reserves terabytes of address space: no ulimit -v
// Under an address-space limit (3 GB), an 8000 x 8000 frame that must be held whole (bench
// renders whole frames) is refused with exit code 2 naming the limit, before any work; PoCL's
// lazy allocation used to end the process with an assertion. `render` of the same size goes in
// bands of a fraction of the memory (image/poster.hpp) and succeeds under the same limit.
TEST(ResourceLimits, AddressSpaceLimitIsACleanRefusal) {
  const auto dir = test::fresh_dir("memory_limit");
  const auto out = dir / "big.png", said = dir / "said.txt", json = dir / "b.json";
  auto run_limited = [&](const std::string& args) {
    const std::string command = "ulimit -v 3000000; " + std::string(FRACTALIS_EXECUTABLE) + " " +
                                args + " > /dev/null 2> " + said.string();
    return std::system(("bash -c '" + command + "'").c_str());
  };
  int status = run_limited("bench --scene menger --size 8000x8000 --frames 1 --runs 1 --json " +
                           json.string());
  ASSERT_TRUE(WIFEXITED(status)) << test::read_file(said);
  EXPECT_EQ(WEXITSTATUS(status), 2) << test::read_file(said);
  EXPECT_NE(test::read_file(said).find("--size 8000x8000: needs "), std::string::npos)
      << test::read_file(said);
  EXPECT_NE(test::read_file(said).find("address-space limit (ulimit -v"), std::string::npos)
      << test::read_file(said);
  EXPECT_FALSE(std::filesystem::exists(json));

  status = run_limited("render --scene menger --size 8000x8000 --out " + out.string());
  ASSERT_TRUE(WIFEXITED(status)) << test::read_file(said);
  EXPECT_EQ(WEXITSTATUS(status), 0) << test::read_file(said);
  int w = 0, h = 0, channels = 0;
  ASSERT_TRUE(stbi_info(out.c_str(), &w, &h, &channels));
  EXPECT_EQ(w, 8000);
  EXPECT_EQ(h, 8000);
}
#endif

void make_file(const std::filesystem::path& file, size_t bytes, time_t mtime_s) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << std::string(bytes, 'x');
  const timespec times[2] = {{mtime_s, 0}, {mtime_s, 0}};
  utimensat(AT_FDCWD, file.c_str(), times, 0);
}

// Programs go least recently used first (by PoCL's last_accessed marker) until the cache fits,
// never one used in the last two minutes (another process may be loading it); temporary files
// (a killed build's preprocessed source) go once they are ten minutes old, whatever their size.
TEST(ResourceLimits, KernelCacheIsTrimmedLeastRecentlyUsedFirst) {
  const auto dir = test::fresh_dir("kernel_cache");
  const time_t now = std::time(nullptr);
  // Four programs of 1000 bytes, used 4, 3, 2 and 1 hours ago (the folder names do not sort so).
  const char* programs[] = {"AB/ZZZ", "CD/AAA", "AB/MMM", "EF/BBB"};
  for (int i = 0; i < 4; ++i) {
    make_file(dir / programs[i] / "program.bc", 900, now);
    make_file(dir / programs[i] / "fr_render" / "1-1-1" / "fr_render" PLUGIN_SUFFIX, 100, now);
    make_file(dir / programs[i] / "last_accessed", 0, now - 3600 * (4 - i));
  }
  make_file(dir / "tempfile_old", 5000, now - 3600);
  make_file(dir / "tempfile_new", 5000, now);  // a build may be writing it
  // A fifth program just used, and (last) one used 5 hours ago: only the old one may go.
  make_file(dir / "GH/NEW" / "program.bc", 1000, now);
  make_file(dir / "GH/NEW" / "last_accessed", 0, now - 30);
  make_file(dir / "GH/OLD" / "program.bc", 1000, now);
  make_file(dir / "GH/OLD" / "last_accessed", 0, now - 5 * 3600);
  const KernelCacheTrim trim = trim_kernel_cache(dir, 3500);
  EXPECT_EQ(trim.bytes_before, 6000u) << "temporary files do not count";
  EXPECT_EQ(trim.bytes_after, 3000u);
  EXPECT_EQ(trim.programs_removed, 3);
  EXPECT_EQ(trim.temp_files_removed, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "AB/ZZZ")) << "used longest ago";
  EXPECT_FALSE(std::filesystem::exists(dir / "CD/AAA"));
  EXPECT_TRUE(std::filesystem::exists(dir / "AB/MMM/program.bc"));
  EXPECT_TRUE(std::filesystem::exists(dir / "EF/BBB/program.bc")) << "used last";
  EXPECT_FALSE(std::filesystem::exists(dir / "tempfile_old"));
  EXPECT_TRUE(std::filesystem::exists(dir / "tempfile_new"));
  EXPECT_FALSE(std::filesystem::exists(dir / "GH/OLD"));
  EXPECT_TRUE(std::filesystem::exists(dir / "GH/NEW/program.bc")) << "used half a minute ago";
  EXPECT_EQ(folder_bytes(dir), 3000u + 5000u);
}

// The cache's place and `fractalis cache --clear`, from a user's side: a render fills
// $XDG_CACHE_HOME/fractalis/kernels, the command lists it, --clear empties it.
TEST(ResourceLimits, CacheCommandShowsAndClears) {
  const auto home = test::fresh_dir("cache_home");
  // A fresh cache compiles the kernels with LLVM, whose allocations LeakSanitizer reports as
  // PoCL's leaks in the sanitizer build; none is fractalis's.
  const std::string env =
      "env -u POCL_CACHE_DIR ASAN_OPTIONS=detect_leaks=0 XDG_CACHE_HOME=" + home.string() + " ";
  const std::string exe = std::string(FRACTALIS_EXECUTABLE);
  const auto out = home / "said.txt";
  ASSERT_EQ(std::system((env + exe + " render --scene menger --size 16x16 --out " +
                         (home / "m.png").string() + " > /dev/null 2>&1")
                            .c_str()),
            0);
  const auto kernels = home / "fractalis" / "kernels";
  EXPECT_GT(folder_bytes(kernels), 0u) << "PoCL compiled into fractalis's folder";
  ASSERT_EQ(std::system((env + exe + " cache > " + out.string()).c_str()), 0);
  EXPECT_NE(test::read_file(out).find("cache folder: " + (home / "fractalis").string()),
            std::string::npos)
      << test::read_file(out);
  EXPECT_NE(test::read_file(out).find("  kernels  "), std::string::npos) << test::read_file(out);
  ASSERT_EQ(std::system((env + exe + " cache --clear > " + out.string()).c_str()), 0);
  EXPECT_NE(test::read_file(out).find("cleared"), std::string::npos) << test::read_file(out);
  EXPECT_EQ(folder_bytes(kernels), 0u);
  EXPECT_FALSE(std::filesystem::exists(kernels));
  // A POCL_CACHE_DIR the user set is theirs: neither cleared nor trimmed.
  const auto theirs = home / "theirs";
  // Over the 16 MiB bound the render below sets, and old: a trim would take it first.
  make_file(theirs / "AB" / "PROGRAM" / "program.bc", 17u << 20, std::time(nullptr) - 86400);
  const std::string their_env = "env POCL_CACHE_DIR=" + theirs.string() +
                                " ASAN_OPTIONS=detect_leaks=0 XDG_CACHE_HOME=" + home.string() +
                                " ";
  ASSERT_EQ(std::system((their_env + exe + " cache --clear > " + out.string()).c_str()), 0);
  EXPECT_NE(test::read_file(out).find("which you set: not fractalis's to clear or bound"),
            std::string::npos)
      << test::read_file(out);
  ASSERT_EQ(std::system((their_env + exe + " render --scene menger --size 8x8 --set " +
                         "cache.kernel_cache_mib=16 --out " + (home / "t.png").string() +
                         " > /dev/null 2>&1")
                            .c_str()),
            0);
  EXPECT_TRUE(std::filesystem::exists(theirs / "AB" / "PROGRAM" / "program.bc"));
}

}  // namespace
}  // namespace fr
