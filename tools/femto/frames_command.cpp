// `femto frames out.npy`: the time bins of a transient volume as PNG frames
// with one exposure for the whole sequence, optionally in false colour, as a
// running integral (continuous emission), a contact sheet, a GIF and an MP4.
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

#include <tbb/parallel_for.h>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/film/npy_volume.h>
#include <femto/film/transient_output.h>
#include <femto/film/volume_info.h>
#include <femto/film/volume_scan.h>
#include <femto/view/contact_sheet.h>
#include <femto/view/display.h>
#include <femto/view/frame_label.h>
#include <femto/view/running_integral.h>

#include "command_options.h"
#include "commands.h"
#include "ffmpeg.h"
#include "view_options.h"

namespace fs = std::filesystem;

namespace femto::cli {
namespace {

struct FramesSettings {
  std::string volume;
  std::string output;
  ExposureSettings exposure;
  std::string bins;
  int every = 1;
  bool runningIntegral = false;
  bool label = false;
  bool contactSheet = false;
  int sheetCount = 16;
  int sheetColumns = 4;
  bool gif = false;
  bool mp4 = false;
  int fps = 24;
};

/// `-o` or `<volume stem>_pngs` beside the volume.
fs::path outputDir(const FramesSettings& settings) {
  if (!settings.output.empty()) return settings.output;
  fs::path volume(settings.volume);
  return volume.parent_path() / (volume.stem().string() + "_pngs");
}

int writeFramePngs(const FramesSettings& settings) {
  const NpyVolume volume = NpyVolume::open(settings.volume);
  // Not a structured binding: the lambdas below capture these, which clang
  // before 16 refuses (the fuzz build, tools/fuzz, uses Debian's clang 14).
  const auto range = parseBinRange(settings.bins, volume.bins());
  const int first = range.first, end = range.second;
  fs::path ffmpeg;
  if (settings.gif || settings.mp4) ffmpeg = findFfmpeg(settings.gif ? "--gif" : "--mp4");  // fail before the work
  const bool cumulative = settings.runningIntegral;
  // The running integral starts from the light that arrived before the window.
  std::optional<Bitmap> before;
  if (cumulative) before = readBeforeImage(settings.volume, volume.width(), volume.height());
  const float exposure = resolveExposure(
      settings.exposure, [&] { return volumeLuminances(volume, first, end, cumulative, before ? &*before : nullptr); });

  const fs::path dir = outputDir(settings);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(str("cannot create \"", dir.string(), "\": ", ec.message()));
  removeStaleFrames(dir, ".png");

  // Shown bins: first, first + every, ... < end; the sheet takes some of them.
  const int shown = (end - first + settings.every - 1) / settings.every;
  std::vector<int> sheetIndex(size_t(shown), -1);
  const std::vector<int> sheetFramesShown = sheetFrames(shown, settings.sheetCount);
  for (size_t i = 0; i < sheetFramesShown.size(); ++i) sheetIndex[size_t(sheetFramesShown[i])] = int(i);
  std::unique_ptr<ContactSheet> sheet;
  if (settings.contactSheet)
    sheet = std::make_unique<ContactSheet>(volume.width(), volume.height(), int(sheetFramesShown.size()),
                                           settings.sheetColumns, 2);

  // --label: each frame's bin centre in OPL from the sidecar, else its index.
  const std::optional<VolumeInfo> info = readVolumeInfo(settings.volume);
  auto labelOf = [&](int bin) { return info ? binLabel(info->grid, bin) : str("bin ", bin); };

  // The running integral starts at bin 0 whatever is shown, so a frame's
  // values do not depend on --bins.
  std::vector<double> sum;
  if (before) {
    sum.resize(size_t(volume.width()) * volume.height() * 3);
    for (int y = 0; y < volume.height(); ++y)
      for (int x = 0; x < volume.width(); ++x)
        for (int c = 0; c < 3; ++c) sum[(size_t(y) * volume.width() + x) * 3 + c] = before->pixel(x, y)[c];
  }
  const int batch = framesPerBatch(volume, VolumeReadBudgetBytes);
  for (int b0 = cumulative ? 0 : first; b0 < end; b0 += batch) {
    const int count = std::min(batch, end - b0);
    std::vector<Bitmap> frames = readFrames(volume, b0, count);
    if (cumulative) accumulateFrames(frames, sum);
    auto writeFrame = [&](int k) {
      const int bin = b0 + k;
      if (bin < first || (bin - first) % settings.every != 0) return;
      Bitmap image = displayImage(frames[size_t(k)], exposure, settings.exposure.falseColour);
      if (settings.label) drawLabel(image, labelOf(bin));
      writePNG(dir / frameFileName(bin, volume.bins(), ".png"), image);
      if (int index = sheetIndex[size_t((bin - first) / settings.every)]; sheet && index >= 0)
        sheet->place(index, image);
    };
    ForkJoinEdges edges;
    tbb::parallel_for(0, count, edges.task(writeFrame));
    edges.join();
  }
  std::cout << "wrote " << shown << " frames (bins " << first << " to " << end - 1;
  if (settings.every > 1) std::cout << ", every " << settings.every;
  if (info)
    std::cout << ", OPL " << info->grid.start + first * info->grid.binWidth << " to "
              << info->grid.start + end * info->grid.binWidth;
  std::cout << (cumulative ? (before ? ", running integral from the light before the window" : ", running integral")
                           : "")
            << ") to " << dir.string() << '\n';
  if (sheet) {
    writePNG(dir / "contact_sheet.png", sheet->image());
    std::cout << "wrote " << (dir / "contact_sheet.png").string() << '\n';
  }
  const std::string pattern = (dir / "frame_*.png").string();
  for (const auto& [wanted, name] :
       {std::pair(settings.gif, "sequence.gif"), std::pair(settings.mp4, "sequence.mp4")}) {
    if (!wanted) continue;
    encodeSequence(ffmpeg, pattern, settings.fps, dir / name);
    std::cout << "wrote " << (dir / name).string() << '\n';
  }
  return 0;
}

}  // namespace

Command addFramesCommand(CLI::App& app) {
  auto settings = std::make_shared<FramesSettings>();
  CLI::App* command =
      app.add_subcommand("frames", "Write the time bins of a transient volume (.npy) as PNG frames, GIF, MP4");
  addVolumeArgument(*command, settings->volume);
  addOutputOption(*command, settings->output, "Folder for the frames (default: <volume stem>_pngs)", "DIR");
  addExposureOptions(*command, settings->exposure);
  addBinRangeOption(*command, settings->bins, "Only bins FIRST to END-1 (default: all)");
  addCountOption(*command, "--every", settings->every, "Only every K-th bin of the range", "K");
  command->add_flag("--running-integral", settings->runningIntegral,
                    "Show the running integral over time: the view of a continuous source switched on at time 0");
  command->add_flag("--label", settings->label,
                    "Burn each frame's time into its top-left corner (bin centre in OPL from the volume's sidecar)");
  command->add_flag("--contact-sheet", settings->contactSheet, "Also write contact_sheet.png (evenly spaced frames)");
  addCountOption(*command, "--sheet-frames", settings->sheetCount, "Frames on the contact sheet (default 16)");
  addCountOption(*command, "--sheet-columns", settings->sheetColumns, "Columns of the contact sheet (default 4)");
  command->add_flag("--gif", settings->gif, "Also write sequence.gif (needs ffmpeg)");
  command->add_flag("--mp4", settings->mp4, "Also write sequence.mp4, H.264 (needs ffmpeg)");
  addCountOption(*command, "--fps", settings->fps, "Frames per second of the GIF/MP4 (default 24)");
  return [settings] { return writeFramePngs(*settings); };
}

}  // namespace femto::cli
