#include "viewer/viewer_server.h"

#include <poll.h>
#include <sys/socket.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "viewer/viewer_page.h"

namespace pathspace::viewer {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;

namespace {

std::string error_message(const std::string& what) { return nlohmann::json{{"error", what}}.dump(); }

// The value of `key` in the query of `target` ("/ws?token=abc"), or "" when absent.
std::string query_value(const std::string& target, const std::string& key) {
  const size_t q = target.find('?');
  if (q == std::string::npos) return "";
  size_t at = q + 1;
  while (at < target.size()) {
    const size_t end = std::min(target.find('&', at), target.size());
    const std::string pair = target.substr(at, end - at);
    if (pair.rfind(key + "=", 0) == 0) return pair.substr(key.size() + 1);
    at = end + 1;
  }
  return "";
}

std::string path_of(const std::string& target) { return target.substr(0, target.find('?')); }

}  // namespace

struct ViewerServer::Impl {
  std::shared_ptr<ViewerBackend> backend;
  std::string address, token;
  net::io_context ioc;
  tcp::acceptor acceptor{ioc};
  std::atomic<bool> stopping{false};
  std::mutex mutex;  // guards sockets and threads
  std::set<int> sockets;
  std::vector<std::thread> threads;
  std::thread accept_thread;

  void accept_loop() {
    while (!stopping) {
      tcp::socket socket(ioc);
      boost::system::error_code ec;
      acceptor.accept(socket, ec);
      if (ec || stopping) break;
      std::lock_guard<std::mutex> lock(mutex);
      sockets.insert(socket.native_handle());
      threads.emplace_back([this, s = std::move(socket)]() mutable { serve(std::move(s)); });
    }
  }

  // Forgets a connection's socket while it is still open: after close(2) its number may already
  // belong to the next connection.
  void forget(int fd) {
    std::lock_guard<std::mutex> lock(mutex);
    sockets.erase(fd);
  }

  void serve(tcp::socket socket) {
    const int fd = socket.native_handle();
    try {
      beast::flat_buffer buffer;
      http::request_parser<http::string_body> parser;
      parser.header_limit(8 * 1024);
      parser.body_limit(kMaxMessageBytes);
      http::read(socket, buffer, parser);
      const http::request<http::string_body> request = parser.release();
      const std::string target(request.target());
      if (!token.empty() && query_value(target, "token") != token) {
        respond(socket, request, http::status::forbidden, "text/plain", "this viewer needs its token: use the URL it printed\n");
      } else if (path_of(target) == "/ws" && websocket::is_upgrade(request)) {
        websocket::stream<tcp::socket> ws(std::move(socket));
        try {
          ws.read_message_max(kMaxMessageBytes);
          ws.accept(request);
          talk(ws);
        } catch (const std::exception&) {
        }
        forget(fd);  // before ws closes it
        return;
      } else if (request.method() == http::verb::get && path_of(target) == "/") {
        respond(socket, request, http::status::ok, "text/html; charset=utf-8", kViewerPage);
      } else {
        respond(socket, request, http::status::not_found, "text/plain", "not found\n");
      }
    } catch (const std::exception&) {
      // A client that closes, sends garbage or breaks the protocol ends its own connection only.
    }
    forget(fd);  // the socket closes when this function returns
  }

  static void respond(tcp::socket& socket, const http::request<http::string_body>& request, http::status status,
                      const char* type, const std::string& body) {
    http::response<http::string_body> response(status, request.version());
    response.set(http::field::content_type, type);
    response.set(http::field::cache_control, "no-store");
    response.keep_alive(false);
    response.body() = body;
    response.prepare_payload();
    http::write(socket, response);
    boost::system::error_code ec;
    socket.shutdown(tcp::socket::shutdown_send, ec);
  }

  // Serves one page: its commands, and each frame it asks for once there is a newer one. While a
  // frame is wanted, the wait polls the socket (also for its end), so that a command (a camera move) is read and
  // applied at once rather than after the frame in flight, which can be a whole pass away. A command
  // that arrived in the same read as the frame request sits in Beast's buffer, not the socket's: it
  // is read after that frame.
  void talk(websocket::stream<tcp::socket>& ws) {
    uint64_t sent = 0;
    bool frame_wanted = false;
    while (!stopping) {
      if (frame_wanted) {
        if (std::optional<Frame> frame = backend->next_frame(sent, std::chrono::milliseconds(5))) {
          frame_wanted = false;
          sent = frame->sequence;
          send_text(ws, frame->stats_json);
          ws.binary(true);
          ws.write(net::buffer(*frame->png));
          continue;
        }
        if (!readable(ws.next_layer().native_handle())) continue;
      }
      beast::flat_buffer buffer;
      ws.read(buffer);
      if (!ws.got_text()) {
        send_text(ws, error_message("commands are text messages"));
        continue;
      }
      try {
        const Command command = parse_command(beast::buffers_to_string(buffer.data()));
        if (std::holds_alternative<FrameRequest>(command)) {
          frame_wanted = true;
        } else if (const std::optional<std::string> reply = backend->apply(command)) {
          send_text(ws, *reply);
        }
      } catch (const Error& e) {
        send_text(ws, error_message(e.what()));
      }
    }
  }

  // Data or the end of the stream waits on the socket (poll(2) without waiting).
  static bool readable(int fd) {
    pollfd p{fd, POLLIN, 0};
    return ::poll(&p, 1, 0) > 0;
  }

  static void send_text(websocket::stream<tcp::socket>& ws, const std::string& text) {
    ws.text(true);
    ws.write(net::buffer(text));
  }
};

ViewerServer::ViewerServer(std::shared_ptr<ViewerBackend> backend, const std::string& address, uint16_t port, std::string token)
    : impl_(std::make_unique<Impl>()) {
  impl_->backend = std::move(backend);
  impl_->address = address;
  impl_->token = std::move(token);
  boost::system::error_code ec;
  const net::ip::address ip = net::ip::make_address(address, ec);
  if (ec) throw Error(fmt::format("--listen {}: not an IP address", address));
  const tcp::endpoint endpoint(ip, port);
  impl_->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl_->acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (!ec) impl_->acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw Error(fmt::format("cannot listen on {}:{}: {}", address, port, ec.message()));
  impl_->accept_thread = std::thread([this] { impl_->accept_loop(); });
}

ViewerServer::~ViewerServer() {
  impl_->stopping = true;
  // shutdown(2) wakes the threads blocked in accept() and read() (closing from another thread would not).
  ::shutdown(impl_->acceptor.native_handle(), SHUT_RDWR);
  impl_->accept_thread.join();
  std::vector<std::thread> threads;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    for (const int fd : impl_->sockets) ::shutdown(fd, SHUT_RDWR);
    threads.swap(impl_->threads);
  }
  for (std::thread& t : threads) t.join();
}

uint16_t ViewerServer::port() const { return impl_->acceptor.local_endpoint().port(); }

std::string ViewerServer::url() const {
  const std::string host = impl_->address.find(':') != std::string::npos ? "[" + impl_->address + "]" : impl_->address;
  return fmt::format("http://{}:{}/{}", host, port(), impl_->token.empty() ? "" : "?token=" + impl_->token);
}

}  // namespace pathspace::viewer
