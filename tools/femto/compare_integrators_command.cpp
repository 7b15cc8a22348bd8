// `femto compare SCENE.xml -i A -i B ...`: integrators on a scene at equal CPU
// budgets (docs/compare.md). `femto compare REF TEST` compares two files
// (compare_command.cpp); a first argument ending in .xml is a scene and comes
// here. The engine is Python (tools/compare/compare_integrators.py, with
// Debian's numpy and matplotlib), copied beside the program at build and
// install time (<prefix>/share/femto/compare): this front finds it from the
// executable's own path and runs it with python3, passing itself as --femto.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"

namespace fs = std::filesystem;

namespace femto::cli {

bool isSceneComparison(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) != "compare") return false;
  const std::string first = argv[2];
  return first.size() > 4 && first.compare(first.size() - 4, 4, ".xml") == 0;
}

int runSceneComparison(int argc, char** argv) {
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  if (ec) {
    std::cerr << "error: femto compare SCENE: cannot find the femto program's own path (/proc/self/exe)\n";
    return 1;
  }
  const fs::path script = self.parent_path().parent_path() / "share" / "femto" / "compare" / "compare_integrators.py";
  if (!fs::exists(script)) {
    std::cerr << "error: femto compare SCENE needs its comparison scripts in \"" << script.string()
              << "\" (built and installed with femto: rebuild or reinstall it)\n";
    return 1;
  }
  const char* python = std::getenv("FEMTO_PYTHON");
  const std::string interpreter = python && *python ? python : FEMTO_PYTHON3;
  std::vector<std::string> words{interpreter, script.string(), "--femto", self.string()};
  for (int i = 2; i < argc; ++i) words.emplace_back(argv[i]);
  std::vector<char*> args;
  for (std::string& w : words) args.push_back(w.data());
  args.push_back(nullptr);
  std::cout.flush();
  execvp(args[0], args.data());
  std::cerr << "error: femto compare SCENE runs Python, and \"" << interpreter
            << "\" could not be started: install python3 with numpy and matplotlib "
               "(apt-get install python3-numpy python3-matplotlib) or set FEMTO_PYTHON\n";
  return 1;
}

}  // namespace femto::cli
