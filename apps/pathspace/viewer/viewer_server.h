// The HTTP and WebSocket server of `pathspace view` (Boost.Beast, docs/viewer.md): GET / serves the
// page (viewer_page.h), /ws upgrades to a WebSocket that carries the protocol of viewer_protocol.h.
// One thread accepts, one thread serves each connection (blocking reads and writes); a client
// waits for its own frames, so a slow one receives fewer and never holds the renderer back.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "viewer/viewer_protocol.h"

namespace pathspace::viewer {

// One encoded frame and the statistics that go with it (a JSON object, text).
struct Frame {
  uint64_t sequence = 0;  // 1, 2, ... in the order frames were made
  std::shared_ptr<const std::string> png;
  std::string stats_json;
};

// What the server needs from the viewer. Called from the connection threads.
class ViewerBackend {
 public:
  virtual ~ViewerBackend() = default;
  // The newest frame if its sequence is above `after`, waiting up to `wait` for one; nullopt else.
  virtual std::optional<Frame> next_frame(uint64_t after, std::chrono::milliseconds wait) = 0;
  // Acts on a command other than FrameRequest: its reply to the client (a JSON object), if any.
  // Throws pathspace::Error when it cannot (the client gets {"error": what}).
  virtual std::optional<std::string> apply(const Command& command) = 0;
};

class ViewerServer {
 public:
  // Listens on address:port (port 0: a free one). A non-empty token is required as ?token= on
  // every request (the page passes its own on to the WebSocket). Throws pathspace::Error when the
  // address cannot be bound.
  ViewerServer(std::shared_ptr<ViewerBackend> backend, const std::string& address, uint16_t port, std::string token);
  // Closes the listening socket and every connection, and joins their threads.
  ~ViewerServer();
  ViewerServer(const ViewerServer&) = delete;
  ViewerServer& operator=(const ViewerServer&) = delete;

  uint16_t port() const;
  // http://address:port/ with the token's query.
  std::string url() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pathspace::viewer
