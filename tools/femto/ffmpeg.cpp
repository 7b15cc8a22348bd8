#include "ffmpeg.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <sstream>

#include <femto/base/error.h>

namespace femto::cli {

std::filesystem::path findFfmpeg(const std::string& why) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / "ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  throw Error(str(why, " needs ffmpeg, which is not on PATH (Debian: apt-get install ffmpeg)"));
}

void encodeSequence(const std::filesystem::path& ffmpeg, const std::string& frames, int fps,
                    const std::filesystem::path& output) {
  std::vector<std::string> args = {ffmpeg.string(), "-y", "-loglevel", "error", "-framerate", std::to_string(fps),
                                   "-pattern_type", "glob", "-i", frames};
  if (output.extension() == ".gif") {
    // One palette computed from the whole sequence, so colours do not flicker.
    args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=bayer"});
  } else {
    // yuv420p for players that know nothing else; H.264 wants even sizes.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                             "-crf", "18"});
  }
  args.push_back(output.string());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(str("cannot start ffmpeg for \"", output.string(), "\""));
  if (pid == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(str("ffmpeg failed to write \"", output.string(), "\" (its messages are above)"));
}

}  // namespace femto::cli
