#include <femto/viewer/view_server.h>

#include <bit>
#include <charconv>
#include <sstream>
#include <string>

#include <httplib.h>

#include <femto/base/error.h>
#include <femto/core/flat_json.h>
#include <femto/viewer/page_assets.h>

namespace femto {

// The API sends floats as they lie in memory; the page reads them as little-endian.
static_assert(std::endian::native == std::endian::little, "the viewer's float32 responses assume little-endian");

struct ViewServer::Routes {
  std::vector<std::unique_ptr<ViewedRender>> renders;
  httplib::Server http;
  int port = 0;
};

namespace {

void sendFloats(httplib::Response& response, const std::vector<float>& values) {
  response.set_content(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float),
                       "application/octet-stream");
}

void notFound(httplib::Response& response, const std::string& why) {
  response.status = 404;
  response.set_content(why + "\n", "text/plain; charset=utf-8");
}

/// A path component matched by \d{1,9} (so it fits an int).
int number(const httplib::Request& request, size_t group) {
  const std::string text = request.matches[group].str();
  int value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

std::string rendersJson(const std::vector<std::unique_ptr<ViewedRender>>& renders) {
  std::ostringstream json;
  json << "[";
  for (size_t i = 0; i < renders.size(); ++i) {
    const ViewedRender& r = *renders[i];
    json << (i ? ",\n " : "") << "{\"index\": " << i << ", \"name\": " << jsonQuote(r.name())
         << ", \"width\": " << r.width() << ", \"height\": " << r.height() << ", \"bins\": " << r.bins()
         << ", \"time\": ";
    if (const std::optional<TimeGrid>& axis = r.timeAxis())
      json << "{\"unit\": \"opl\", \"start\": " << jsonNumber(axis->start)
           << ", \"bin_width\": " << jsonNumber(axis->binWidth) << "}";
    else
      json << "null";
    json << ", \"percentile_stride\": " << r.percentileStride() << "}";
  }
  json << "]\n";
  return json.str();
}

}  // namespace

ViewServer::ViewServer(std::vector<std::unique_ptr<ViewedRender>> renders) : routes_(std::make_unique<Routes>()) {
  routes_->renders = std::move(renders);
  Routes& routes = *routes_;
  httplib::Server& http = routes.http;
  // httplib's default adds SO_REUSEPORT, which lets a second server share a
  // port another is listening on; --port N must fail instead when N is taken.
  http.set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });

  // DNS rebinding: a web page elsewhere may point a name of its own at
  // 127.0.0.1 and read this server through it. The Host header then names
  // that site, so answer only requests addressed to the loopback by number
  // or as localhost.
  http.set_pre_routing_handler([&routes](const httplib::Request& request, httplib::Response& response) {
    const std::string host = request.get_header_value("Host");
    if (host == str("127.0.0.1:", routes.port) || host == str("localhost:", routes.port))
      return httplib::Server::HandlerResponse::Unhandled;
    response.status = 403;
    response.set_content("femto view answers only requests to 127.0.0.1 or localhost\n", "text/plain; charset=utf-8");
    return httplib::Server::HandlerResponse::Handled;
  });

  for (const PageAsset& asset : pageAssets()) {
    auto serve = [&asset](const httplib::Request&, httplib::Response& response) {
      response.set_content(asset.body.data(), asset.body.size(), std::string(asset.contentType));
    };
    http.Get(std::string(asset.path), serve);
    if (asset.path == "/index.html") http.Get("/", serve);
  }

  http.Get("/api/renders", [&routes](const httplib::Request&, httplib::Response& response) {
    response.set_content(rendersJson(routes.renders), "application/json");
  });

  // Every render route starts with its index; a handler gets the render or
  // the request is 404. femto::Error (a pixel or bin outside the volume) is 404 too.
  auto renderRoute = [&routes, &http](
                         const std::string& tail,
                         std::function<void(const ViewedRender&, const httplib::Request&, httplib::Response&)> handle) {
    http.Get(R"(/api/renders/(\d{1,9}))" + tail,
             [&routes, handle](const httplib::Request& request, httplib::Response& response) {
               const size_t index = size_t(number(request, 1));
               if (index >= routes.renders.size())
                 return notFound(response, str("no render ", index, " (", routes.renders.size(), " named)"));
               try {
                 handle(*routes.renders[index], request, response);
               } catch (const Error& e) {
                 notFound(response, e.what());
               }
             });
  };
  renderRoute(R"(/frame/(\d{1,9}))", [](const ViewedRender& r, const httplib::Request& q, httplib::Response& a) {
    sendFloats(a, r.frame(number(q, 2)));
  });
  renderRoute("/steady",
              [](const ViewedRender& r, const httplib::Request&, httplib::Response& a) { sendFloats(a, r.steady()); });
  renderRoute(R"(/profile/(\d{1,9})/(\d{1,9}))",
              [](const ViewedRender& r, const httplib::Request& q, httplib::Response& a) {
                sendFloats(a, r.profile(number(q, 2), number(q, 3)));
              });
  renderRoute(R"(/streak/row/(\d{1,9}))", [](const ViewedRender& r, const httplib::Request& q, httplib::Response& a) {
    sendFloats(a, r.streakRow(number(q, 2)).data);
  });
  renderRoute(R"(/streak/column/(\d{1,9}))",
              [](const ViewedRender& r, const httplib::Request& q, httplib::Response& a) {
                sendFloats(a, r.streakColumn(number(q, 2)).data);
              });
  renderRoute("/brightest", [](const ViewedRender& r, const httplib::Request&, httplib::Response& a) {
    a.set_content(str("{\"bin\": ", r.brightestBin(), "}\n"), "application/json");
  });
  renderRoute("/percentile", [](const ViewedRender& r, const httplib::Request& q, httplib::Response& a) {
    double percent = 99.5;
    const std::string text = q.get_param_value("p");
    if (!text.empty()) {
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), percent);
      if (ec != std::errc() || end != text.data() + text.size() || !(percent >= 0.0 && percent <= 100.0))
        return notFound(a, str("percentile \"", text, "\" is not a number from 0 to 100"));
    }
    a.set_content(str("{\"percentile\": ", jsonNumber(percent), ", \"luminance\": ",
                      jsonNumber(r.percentileLuminance(percent)), ", \"stride\": ", r.percentileStride(), "}\n"),
                  "application/json");
  });

  http.set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (response.body.empty()) response.set_content(str("HTTP ", response.status, "\n"), "text/plain; charset=utf-8");
  });
}

ViewServer::~ViewServer() = default;

int ViewServer::bind(int port) {
  // 127.0.0.1 only: nothing off this machine can reach the renders.
  const char* host = "127.0.0.1";
  const int bound = port == 0                                ? routes_->http.bind_to_any_port(host)
                    : routes_->http.bind_to_port(host, port) ? port
                                                             : -1;
  if (bound <= 0)
    throw Error(port == 0 ? str("cannot listen on any port of ", host)
                          : str("cannot listen on ", host, ":", port, " (is the port taken? try another --port)"));
  routes_->port = bound;
  return bound;
}

void ViewServer::run() {
  if (!routes_->http.listen_after_bind()) throw Error("the viewer's server stopped with an error");
}

bool ViewServer::running() const { return routes_->http.is_running(); }

void ViewServer::stop() { routes_->http.stop(); }

}  // namespace femto
