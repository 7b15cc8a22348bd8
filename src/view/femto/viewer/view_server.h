#pragma once
// The HTTP server behind `femto view` (docs/viewing.md): the viewer page and
// a read-only API over the renders named on the command line, on the
// loopback interface only. Renders are named by their index in that list,
// never by a path, so no request can reach another file; only GET is
// answered, and anything not listed below is 404.
//
//   GET /                                   the page (index.html, viewer.js, viewer.css)
//   GET /api/renders                        JSON: each render's name, size, bins, time axis
//   GET /api/renders/R/frame/B              bin B: height x width x RGB float32 (little-endian)
//   GET /api/renders/R/steady               the sum over bins, same layout
//   GET /api/renders/R/profile/X/Y          pixel (X, Y): bins x RGB float32
//   GET /api/renders/R/streak/row/Y         bins x width x RGB float32 (time downwards)
//   GET /api/renders/R/streak/column/X      height x bins x RGB float32 (time to the right)
//   GET /api/renders/R/percentile?p=P       JSON: the P-th percentile of voxel luminance
#include <memory>
#include <vector>

#include <femto/viewer/viewed_render.h>

namespace femto {

class ViewServer {
 public:
  explicit ViewServer(std::vector<std::unique_ptr<ViewedRender>> renders);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// Bind to 127.0.0.1:`port`, or a free port when `port` is 0; returns the
  /// port. An error says why when it cannot (the port is taken, say).
  int bind(int port);
  /// Serve until stop() (call bind first).
  void run();
  /// Whether run() is serving; stop() from another thread once it is.
  bool running() const;
  void stop();

 private:
  struct Routes;
  std::unique_ptr<Routes> routes_;
};

}  // namespace femto
