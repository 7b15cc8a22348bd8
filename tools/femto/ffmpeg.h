#pragma once
// Running ffmpeg (the Debian package `ffmpeg`) to turn PNG frames into a GIF
// or an MP4. femto does not link it: it is a separate program, needed only
// for these two outputs.
#include <filesystem>
#include <string>
#include <vector>

namespace femto::cli {

/// The ffmpeg executable on PATH; a femto::Error naming `why` (e.g. "--gif")
/// and how to install it when there is none.
std::filesystem::path findFfmpeg(const std::string& why);

/// Encode `frames` (a glob such as DIR/frame_*.png, in name order) at `fps`
/// frames per second into `output` (.gif: one palette for the sequence;
/// .mp4: H.264, yuv420p, sizes padded to even). Throws femto::Error if
/// ffmpeg fails.
void encodeSequence(const std::filesystem::path& ffmpeg, const std::string& frames, int fps,
                    const std::filesystem::path& output);

}  // namespace femto::cli
