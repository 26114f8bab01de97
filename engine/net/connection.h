// One side of a connection in Chocolate Doom's protocol (its net_common.c): packets
// out (each sent through the caller's outbox), reliable packets numbered, sent one at a
// time and again every second until acknowledged, reliable packets in taken once and
// in order and each acknowledged, a keepalive after a second of silence, and the other
// side given up after 30 seconds without a word. Client and server each keep one per
// peer.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "engine/net/protocol.h"

namespace p3d::net {

// Whether more than `ms` milliseconds went by from `then` to `now` (the clock may wrap).
inline bool later(uint32_t now, uint32_t then, uint32_t ms) { return now - then > ms; }
// A tic still missing this long after it was asked for is asked for again; a peer that
// has sent no tic for this long is asked for its next ones (net_client.c, net_server.c).
constexpr uint32_t kAskAgainAfter = 300, kDeadlockAfter = 1000;

class Connection {
 public:
  explicit Connection(uint32_t now_ms) : last_send_at_(now_ms), last_receive_at_(now_ms) {}

  void send(std::vector<uint8_t> bytes, uint32_t now_ms);
  PacketWriter new_reliable(PacketType type);  // numbered: fill it, then queue_reliable
  void queue_reliable(PacketWriter packet);
  // A packet from the other side, its type read: the reliable sequence and the
  // acknowledgements are dealt with here. Returns the type to act on (reliable bit
  // cleared), or nullopt when there is nothing more to do with it.
  std::optional<uint32_t> receive(PacketReader& in, uint32_t now_ms);
  // Resends the first reliable packet when due; a keepalive after a second of silence.
  void run(uint32_t now_ms);
  bool timed_out(uint32_t now_ms) const;
  std::vector<std::vector<uint8_t>> take_outgoing() { return std::exchange(outgoing_, {}); }

 private:
  struct Reliable {
    std::vector<uint8_t> bytes;
    int64_t sent_at = -1;
    uint8_t seq = 0;
  };
  std::vector<std::vector<uint8_t>> outgoing_;
  std::deque<Reliable> reliable_out_;  // the first is sent (again every second) until acknowledged
  uint8_t send_seq_ = 0, recv_seq_ = 0;
  uint32_t last_send_at_ = 0, last_receive_at_ = 0;
};

}  // namespace p3d::net
