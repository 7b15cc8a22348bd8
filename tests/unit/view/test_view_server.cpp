// The `femto view` server (src/view/femto/viewer/view_server.h) over real
// HTTP on the loopback: frames, profiles, streaks, the percentile and the
// steady sum of a tiny volume with one hot voxel hold exactly what the volume
// holds; everything not named (other renders, paths, methods, hosts) is refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include <httplib.h>

#include <femto/film/npy_volume.h>
#include <femto/viewer/view_server.h>

namespace fs = std::filesystem;

namespace femto {
namespace {

constexpr int H = 5, W = 7, Bins = 9;
constexpr int HotY = 3, HotX = 2, HotBin = 6;
constexpr float Hot[3] = {4.0f, 2.0f, 1.0f};

fs::path writeHotVolume(const std::string& name, bool sidecar) {
  fs::path dir = fs::path(::testing::TempDir()) / ("femto_view_server_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / name;
  NpyVolume volume = NpyVolume::create(path, H, W, Bins);
  std::vector<float> pixel(size_t(Bins) * 3, 0.0f);
  std::copy_n(Hot, 3, &pixel[size_t(HotBin) * 3]);
  volume.writePixels(HotY, HotX, 1, pixel.data());
  if (sidecar)
    std::ofstream(fs::path(path).replace_extension(".json"))
        << "{\"format\": \"femto transient volume\", \"version\": 1, \"width\": 7, \"height\": 5, \"bins\": 9,"
           " \"time_unit\": \"opl\", \"start_opl\": 3, \"bin_width_opl\": 0.5, \"end_opl\": 7.5}\n";
  return path;
}

std::vector<float> floats(const httplib::Result& result) {
  std::vector<float> values(result->body.size() / sizeof(float));
  std::memcpy(values.data(), result->body.data(), values.size() * sizeof(float));
  return values;
}

/// A server on a free port of 127.0.0.1, serving in a thread for one test.
class ViewServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::vector<std::unique_ptr<ViewedRender>> renders;
    renders.push_back(std::make_unique<ViewedRender>(writeHotVolume("hot.npy", true)));
    server_ = std::make_unique<ViewServer>(std::move(renders));
    port_ = server_->bind(0);
    thread_ = std::thread([this] { server_->run(); });
    while (!server_->running()) std::this_thread::yield();
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
  }
  void TearDown() override {
    server_->stop();
    thread_.join();
  }
  httplib::Result get(const std::string& path) { return client_->Get(path.c_str()); }

  std::unique_ptr<ViewServer> server_;
  int port_ = 0;
  std::thread thread_;
  std::unique_ptr<httplib::Client> client_;
};

TEST_F(ViewServerTest, ListsTheRendersWithTheirTimeAxis) {
  const httplib::Result r = get("/api/renders");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  EXPECT_NE(r->body.find("\"name\": \"hot.npy\", \"width\": 7, \"height\": 5, \"bins\": 9"), std::string::npos)
      << r->body;
  EXPECT_NE(r->body.find("\"time\": {\"unit\": \"opl\", \"start\": 3, \"bin_width\": 0.5}"), std::string::npos)
      << r->body;
  // Names only: the folder the volume lies in is not told.
  EXPECT_EQ(r->body.find(::testing::TempDir()), std::string::npos) << r->body;
}

TEST_F(ViewServerTest, FrameHoldsTheHotVoxelInItsBinOnly) {
  for (int b = 0; b < Bins; ++b) {
    const httplib::Result r = get("/api/renders/0/frame/" + std::to_string(b));
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/octet-stream");
    const std::vector<float> frame = floats(r);
    ASSERT_EQ(frame.size(), size_t(H) * W * 3);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int c = 0; c < 3; ++c) {
          const bool hot = b == HotBin && x == HotX && y == HotY;
          EXPECT_EQ(frame[(size_t(y) * W + x) * 3 + c], hot ? Hot[c] : 0.0f) << b << ' ' << x << ' ' << y;
        }
  }
  EXPECT_EQ(get("/api/renders/0/frame/9")->status, 404);
}

TEST_F(ViewServerTest, ProfilePeaksAtTheHotBin) {
  const std::vector<float> profile = floats(get(str("/api/renders/0/profile/", HotX, "/", HotY)));
  ASSERT_EQ(profile.size(), size_t(Bins) * 3);
  for (int b = 0; b < Bins; ++b)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(profile[size_t(b) * 3 + c], b == HotBin ? Hot[c] : 0.0f) << b;
  const std::vector<float> dark = floats(get(str("/api/renders/0/profile/", HotX + 1, "/", HotY)));
  EXPECT_EQ(dark, std::vector<float>(size_t(Bins) * 3, 0.0f));
  EXPECT_EQ(get("/api/renders/0/profile/7/0")->status, 404);  // x outside
  EXPECT_EQ(get("/api/renders/0/profile/0/5")->status, 404);  // y outside
}

TEST_F(ViewServerTest, StreaksSteadyAndPercentile) {
  const std::vector<float> row = floats(get(str("/api/renders/0/streak/row/", HotY)));
  ASSERT_EQ(row.size(), size_t(W) * Bins * 3);  // width x bins, time downwards
  EXPECT_EQ(row[(size_t(HotBin) * W + HotX) * 3], Hot[0]);
  const std::vector<float> column = floats(get(str("/api/renders/0/streak/column/", HotX)));
  ASSERT_EQ(column.size(), size_t(Bins) * H * 3);  // bins x height, time to the right
  EXPECT_EQ(column[(size_t(HotY) * Bins + HotBin) * 3 + 1], Hot[1]);
  EXPECT_EQ(get("/api/renders/0/streak/row/5")->status, 404);

  const std::vector<float> steady = floats(get("/api/renders/0/steady"));
  ASSERT_EQ(steady.size(), size_t(H) * W * 3);
  EXPECT_EQ(steady[(size_t(HotY) * W + HotX) * 3 + 2], Hot[2]);

  // One non-black voxel: every percentile is its luminance (to the histogram's 2 %).
  const httplib::Result p = get("/api/renders/0/percentile?p=99.5");
  ASSERT_EQ(p->status, 200);
  const double luminance = 0.2126 * Hot[0] + 0.7152 * Hot[1] + 0.0722 * Hot[2];
  const size_t at = p->body.find("\"luminance\": ");
  ASSERT_NE(at, std::string::npos) << p->body;
  EXPECT_NEAR(std::stod(p->body.substr(at + 13)), luminance, 0.022 * luminance) << p->body;
  EXPECT_EQ(get("/api/renders/0/percentile?p=101")->status, 404);
  EXPECT_EQ(get("/api/renders/0/percentile?p=x")->status, 404);
}

TEST_F(ViewServerTest, BrightestBinIsWhereThePageOpens) {
  const httplib::Result r = get("/api/renders/0/brightest");
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->body, str("{\"bin\": ", HotBin, "}\n"));
  EXPECT_EQ(get("/api/renders/1/brightest")->status, 404);
}

TEST(ViewedRender, BrightestBinSumsTheLightOfEveryPixel) {
  fs::path dir = fs::path(::testing::TempDir()) / ("femto_view_brightest_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  NpyVolume volume = NpyVolume::create(dir / "two.npy", H, W, Bins);
  // Bin 2 holds the single brightest voxel (10), bin 5 more light in all (6 + 6): bin 5 wins.
  std::vector<float> pixel(size_t(Bins) * 3, 0.0f);
  for (int c = 0; c < 3; ++c) pixel[2 * 3 + c] = 10.0f, pixel[5 * 3 + c] = 6.0f;
  volume.writePixels(0, 0, 1, pixel.data());
  std::fill(pixel.begin(), pixel.end(), 0.0f);
  for (int c = 0; c < 3; ++c) pixel[5 * 3 + c] = 6.0f;
  volume.writePixels(1, 0, 1, pixel.data());
  EXPECT_EQ(ViewedRender(dir / "two.npy").brightestBin(), 5);
  NpyVolume::create(dir / "black.npy", H, W, Bins);
  EXPECT_EQ(ViewedRender(dir / "black.npy").brightestBin(), 0);
  fs::remove_all(dir);
}

TEST_F(ViewServerTest, ServesThePageAndNothingElse) {
  for (const char* page : {"/", "/index.html", "/viewer.js", "/viewer.css"}) {
    const httplib::Result r = get(page);
    ASSERT_TRUE(r) << page;
    EXPECT_EQ(r->status, 200) << page;
  }
  EXPECT_NE(get("/")->body.find("<script src=\"/viewer.js\">"), std::string::npos);
  for (const char* path : {"/api/renders/1/frame/0", "/api/renders/99999999999/frame/0", "/hot.npy", "/etc/passwd",
                           "/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/api/renders/0/../../hot.npy",
                           "/api/renders/0/frame/-1", "/api/renders/0", "/api/renders/0/frame/0/extra"}) {
    const httplib::Result r = get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 404) << path;
  }
  // No write endpoints: other methods find nothing.
  EXPECT_EQ(client_->Post("/api/renders", "x", "text/plain")->status, 404);
  EXPECT_EQ(client_->Put("/api/renders/0/frame/0", "x", "text/plain")->status, 404);
  EXPECT_EQ(client_->Delete("/api/renders/0")->status, 404);
}

TEST_F(ViewServerTest, RefusesRequestsForAnotherHost) {
  // A page elsewhere that rebinds its own name to 127.0.0.1 sends its Host.
  httplib::Result r = client_->Get("/api/renders", {{"Host", "evil.example:" + std::to_string(port_)}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  r = client_->Get("/api/renders", {{"Host", "localhost:" + std::to_string(port_)}});
  EXPECT_EQ(r->status, 200);
}

TEST(ViewServer, BindsTheLoopbackOnly) {
  std::vector<std::unique_ptr<ViewedRender>> renders;
  renders.push_back(std::make_unique<ViewedRender>(writeHotVolume("bind.npy", false)));
  ViewServer server(std::move(renders));
  const int port = server.bind(0);
  ASSERT_GT(port, 0);
  // Taken: a second server on the same port fails naming it.
  std::vector<std::unique_ptr<ViewedRender>> more;
  more.push_back(std::make_unique<ViewedRender>(writeHotVolume("bind2.npy", false)));
  ViewServer second(std::move(more));
  try {
    second.bind(port);
    FAIL() << "bound a taken port";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(str("127.0.0.1:", port)), std::string::npos) << e.what();
  }
  // The kernel's table of TCP sockets (/proc/net/tcp: local address as
  // hex IPv4:port, state 0A = listening) has the port bound to 127.0.0.1
  // (0100007F, little-endian) and to no other address.
  std::ifstream table("/proc/net/tcp");
  if (!table) GTEST_SKIP() << "no /proc/net/tcp to check the bound address";
  char hexPort[8];
  std::snprintf(hexPort, sizeof hexPort, "%04X", port);
  std::vector<std::string> listening;
  for (std::string line; std::getline(table, line);) {
    std::istringstream fields(line);
    std::string slot, local, remote, state;
    fields >> slot >> local >> remote >> state;
    if (state == "0A" && local.size() > 5 && local.substr(local.size() - 4) == hexPort) listening.push_back(local);
  }
  EXPECT_EQ(listening, std::vector<std::string>{str("0100007F:", hexPort)});
}

}  // namespace
}  // namespace femto
