// Streaming: a transient volume several times larger than a memory limit is
// rendered by the femto program (a child process, so its peak resident memory
// can be measured alone with wait4) and completes with its peak RSS under the
// limit: tiles go to disk as they finish, and frames are cut from the volume a
// batch at a time. The limit applies to the memory the volume costs: the peak
// RSS of the same render with one time bin (libraries, plugins, thread pools:
// over 100 MiB on its own) is measured first and subtracted.
#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <string>
#include <vector>

#include "render_test_util.h"

extern char** environ;

namespace femto {
namespace {

constexpr int Width = 256, Height = 256, Bins = 512;  // 384 MiB of float32 RGB
constexpr long PeakRssLimitKiB = 80 * 1024;           // under 1/4 of the volume

/// Run femto with `args`; returns the child's peak resident set (KiB), -1 if it failed.
long runFemto(std::vector<std::string> args) {
  std::string femto = std::string(FEMTO_BINARY_DIR) + "/bin/femto";
  args.insert(args.begin(), femto);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, femto.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  struct rusage usage {};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return usage.ru_maxrss;
}

/// The test's scene (the ramp integrator, so the volume's content costs
/// nothing) at width x `height` with `filter` as the film's nested rfilter
/// ("" for the default box), rendered by femto with -D bins=`bins`: the
/// child's peak resident set (KiB), -1 if it failed.
long renderRamp(const std::filesystem::path& dir, int height, const std::string& filter, bool frames, int bins) {
  std::filesystem::path scene = dir / "scene.xml";
  std::ofstream(scene) << R"(<scene version="3.0.0">
  <default name="bins" value="1"/>
  <integrator type="test_transient_ramp"/>
  <sensor type="test_film_position">
    <film type="transient">
      <integer name="width" value=")" << Width << R"("/>
      <integer name="height" value=")" << height << R"("/>
      <integer name="temporal_bins" value="$bins"/>
      <float name="bin_width_opl" value="1"/>
      <boolean name="write_frames" value=")" << (frames ? "true" : "false") << R"("/>
      )" << filter << R"(
    </film>
    <sampler type="independent"><integer name="sample_count" value="1"/></sampler>
  </sensor>
</scene>
)";
  return runFemto({"render", scene.string(), "-o", (dir / "out.exr").string(), "-p", FEMTO_TEST_PLUGIN_DIR, "-t", "2",
                   "--no-progress", "--strict", "-D", "bins=" + std::to_string(bins)});
}

TEST(TransientStreaming, VolumeLargerThanTheMemoryLimitIsWrittenWithBoundedPeakMemory) {
  auto dir = test::scratchDir("transient-streaming");
  auto render = [&](int bins) { return renderRamp(dir, Height, "", true, bins); };
  const long baseline = render(1);
  ASSERT_GT(baseline, 0) << "femto failed";
  auto start = std::chrono::steady_clock::now();
  const long peak = render(Bins);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_GT(peak, 0) << "femto failed";

  const uint64_t volumeBytes = uint64_t(Width) * Height * Bins * 3 * sizeof(float);
  ASSERT_GT(volumeBytes / 1024, uint64_t(4 * PeakRssLimitKiB));  // the test means something
  EXPECT_GT(std::filesystem::file_size(dir / "out.npy"), volumeBytes);
  EXPECT_TRUE(std::filesystem::exists(dir / "out_frames" / "frame_00511.exr"));
  std::cout << "peak RSS " << peak / 1024 << " MiB (one bin: " << baseline / 1024 << " MiB) for a "
            << volumeBytes / (1 << 20) << " MiB volume, " << seconds << " s\n";
  EXPECT_LT(peak - baseline, PeakRssLimitKiB);
  std::filesystem::remove_all(dir);
}

TEST(TransientStreaming, AGaussianPixelFilterHoldsABandOfTileRowsNotTheVolume) {
  // A filter wider than a pixel holds tiles until their neighbours come
  // (TransientOutput::consumeBordered): a band of a few tile rows, whatever
  // the image's height. 256 x 1024 pixels x 512 bins: a 1.5 GiB volume
  // against a quarter of it.
  constexpr int TallHeight = 1024;
  auto dir = test::scratchDir("transient-streaming-gaussian");
  auto render = [&](int bins) { return renderRamp(dir, TallHeight, R"(<rfilter type="gaussian"/>)", false, bins); };
  const long baseline = render(1);
  ASSERT_GT(baseline, 0) << "femto failed";
  const long peak = render(Bins);
  ASSERT_GT(peak, 0) << "femto failed";
  const uint64_t volumeBytes = uint64_t(Width) * TallHeight * Bins * 3 * sizeof(float);
  EXPECT_GT(std::filesystem::file_size(dir / "out.npy"), volumeBytes);
  std::cout << "peak RSS " << peak / 1024 << " MiB (one bin: " << baseline / 1024 << " MiB) for a "
            << volumeBytes / (1 << 20) << " MiB volume with a gaussian pixel filter\n";
  EXPECT_LT(uint64_t(peak - baseline) * 1024, volumeBytes / 4);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace femto
