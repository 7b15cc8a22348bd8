// `femto compare REF TEST`: error metrics of a test rendering against a
// reference (steady images or transient .npy volumes), as a table on stdout
// and optionally as JSON. See docs/compare.md.
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <femto/analysis/compare_files.h>
#include <femto/base/error.h>
#include <femto/image/image_io.h>

#include "command_options.h"
#include "commands.h"
#include "compare_report.h"

namespace femto::cli {
namespace {

struct CompareOptions {
  std::string reference, test;
  std::string json, crop, mask, bins;
  double epsilon = DefaultRelMseEpsilon;
};

void writeJsonFile(const std::string& path, const Comparison& c) {
  std::ostringstream text;
  writeComparisonJson(text, c);
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text.str();
    if (!out.flush()) throw Error(str("cannot write \"", path, "\""));
  });
}

int compare(const CompareOptions& o) {
  CompareSettings settings;
  settings.epsilon = o.epsilon;
  if (!o.crop.empty()) settings.crop = parsePixelRect(o.crop, "--crop");
  settings.mask = o.mask;
  if (!o.bins.empty()) settings.bins = parseBinRange(o.bins, "--bins"), settings.binsGiven = true;
  Comparison c = compareFiles(o.reference, o.test, settings);
  // `--json -`: the JSON alone on stdout, for pipes.
  if (o.json == "-") {
    writeComparisonJson(std::cout, c);
    return 0;
  }
  printComparisonTable(std::cout, c);
  if (!o.json.empty()) writeJsonFile(o.json, c);
  return 0;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "Error of a rendering against a reference: steady images (EXR, ...) or transient volumes (.npy)");
  command->add_option("reference", o->reference, "Reference image or .npy volume")->required();
  command->add_option("test", o->test, "Test image or .npy volume (same kind and shape)")->required();
  command->add_option("--json", o->json, "Also write the metrics (and the per-bin curves) as JSON; - for stdout instead of the table")->type_name("FILE");
  command->add_option("--crop", o->crop, "Compare only this rectangle of pixels")->type_name("X,Y,W,H");
  command->add_option("--mask", o->mask, "Compare only pixels where this image (PNG, EXR) is nonzero")
      ->type_name("IMAGE")
      ->check(CLI::ExistingFile);
  addBinRangeOption(*command, o->bins, "Volumes: compare only time bins FIRST..END-1");
  command->add_option("--epsilon", o->epsilon, "relMSE's epsilon: mean (t-r)^2 / (r^2 + epsilon)")
      ->type_name("E")
      ->capture_default_str();
  command->footer(
      "Integrators on a scene at equal CPU budgets: femto compare SCENE.xml -i NAME -i NAME [...] "
      "(a first argument ending in .xml; `femto compare SCENE.xml --help` for its options, docs/compare.md)");
  return [o] { return compare(*o); };
}

}  // namespace femto::cli
