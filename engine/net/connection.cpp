#include "engine/net/connection.h"

#include <utility>

namespace p3d::net {

namespace {

constexpr uint32_t kResendEvery = 1000, kKeepaliveEvery = 1000, kTimeout = 30000;  // ms, as net_common.c

}  // namespace

void Connection::send(std::vector<uint8_t> bytes, uint32_t now_ms) {
  outgoing_.push_back(std::move(bytes));
  last_send_at_ = now_ms;
}

PacketWriter Connection::new_reliable(PacketType type) {
  PacketWriter p(type, true);
  p.u8(send_seq_++);
  return p;
}

void Connection::queue_reliable(PacketWriter packet) {
  Reliable r;
  r.bytes = std::move(packet.bytes());
  r.seq = r.bytes[2];  // after the type: new_reliable's sequence number
  reliable_out_.push_back(std::move(r));
}

std::optional<uint32_t> Connection::receive(PacketReader& in, uint32_t now_ms) {
  auto type = in.u16();
  if (!type) return std::nullopt;
  last_receive_at_ = now_ms;
  if (*type & kReliable) {  // in order, once: anything else is acknowledged and dropped
    const auto seq = in.u8();
    if (!seq) return std::nullopt;
    const bool expected = *seq == recv_seq_;
    if (expected) ++recv_seq_;
    PacketWriter ack(PacketType::kReliableAck);
    ack.u8(recv_seq_);
    send(std::move(ack.bytes()), now_ms);
    if (!expected) return std::nullopt;
    *type &= ~uint32_t(kReliable);
  }
  if (PacketType(*type) == PacketType::kReliableAck) {
    const auto seq = in.u8();
    if (seq && !reliable_out_.empty() && *seq == uint8_t(reliable_out_.front().seq + 1)) {
      reliable_out_.pop_front();
      if (!reliable_out_.empty()) reliable_out_.front().sent_at = -1;  // the next goes at once
    }
    return std::nullopt;
  }
  if (PacketType(*type) == PacketType::kKeepalive) return std::nullopt;
  return *type;
}

void Connection::run(uint32_t now_ms) {
  if (later(now_ms, last_send_at_, kKeepaliveEvery)) send(PacketWriter(PacketType::kKeepalive).bytes(), now_ms);
  if (reliable_out_.empty()) return;
  Reliable& first = reliable_out_.front();
  if (first.sent_at < 0 || later(now_ms, uint32_t(first.sent_at), kResendEvery)) {
    first.sent_at = now_ms;
    send(first.bytes, now_ms);
  }
}

bool Connection::timed_out(uint32_t now_ms) const { return later(now_ms, last_receive_at_, kTimeout); }

}  // namespace p3d::net
