#pragma once
// The viewer page's files (src/view/femto/viewer/page/: plain HTML, JS and
// CSS, nothing fetched from elsewhere), compiled into the program at build
// time (cmake/embed_files.cmake), so `femto view` works the same from the
// build tree, from an install and offline.
#include <span>
#include <string_view>

namespace femto {

struct PageAsset {
  std::string_view path;         // as requested: "/viewer.js"
  std::string_view contentType;  // "text/javascript; charset=utf-8"
  std::string_view body;
};

std::span<const PageAsset> pageAssets();

}  // namespace femto
