#pragma once
/// @file protocol.hpp
/// The subprocess form of the adapter contract (protocol version 2, docs/judge.md): the judge
/// starts the adapter program, which speaks length-prefixed binary messages on its stdin and
/// stdout. Every number crosses as raw little-endian IEEE-754 binary64 bytes, bit for bit.
///
/// Message: u32 length (of type + payload), u8 type, payload.
///   adapter -> judge  'H' hello: UTF-8 JSON {"protocol":2, "library", "version", "kinds",
///                     "queries", "contract":{...}, "mapping"}
///   judge -> adapter  'B' batch: u32 n, then n inputs: for a then b: u8 kind, u16 count,
///                     count f64 values (codec field order)
///   adapter -> judge  'R' results: u32 n, then per input: u8 status (0 ok, 1 threw,
///                     2 unsupported); ok: u8 overlap, u8 has_push, f64 push x, f64 push y,
///                     stored a and stored b (u8 kind, u16 count, count f64); threw: u16 length,
///                     UTF-8 message
///   judge -> adapter  'C' point batch (only to an adapter declaring "contains"): u32 n, then
///                     n inputs: shape, f64 px, f64 py
///   adapter -> judge  'R' results of a point batch: per input u8 status; ok: u8 inside,
///                     stored shape, f64 stored px, f64 stored py; threw: as above
///   judge -> adapter  'P' reproducer request: UTF-8 JSON {"query", "exact", "a":{"kind",
///                     "bits":[16 hex digits per value]}, "b":{...}} ("p":[2 bit strings]
///                     instead of "b" for contains)
///   adapter -> judge  'S' source: {"ext":"js", "source":"..."} as UTF-8 JSON
///   judge -> adapter  'Q' quit (or end of input)

#include "collide/judge/adapter.hpp"

#include <chrono>
#include <string>
#include <sys/types.h>
#include <vector>

namespace collide::judge {

inline constexpr int kProtocolVersion = 2;

/// An adapter program run as a child process.
class Subprocess final : public Adapter {
 public:
  /// Starts argv (argv[0] looked up on PATH) and reads its hello. Throws AdapterError when it
  /// cannot start, says nothing within `timeout`, or speaks another protocol version.
  Subprocess(std::vector<std::string> argv, std::chrono::milliseconds timeout);
  ~Subprocess() override;
  Subprocess(const Subprocess&) = delete;
  Subprocess& operator=(const Subprocess&) = delete;

  const Info& info() const override { return info_; }
  /// One round trip per batch. A batch that times out or kills the adapter is retried input by
  /// input in a fresh process; an input that then hangs is a Hung answer, one that kills it a
  /// Threw answer ("adapter died"), so one bad input costs one case, not the run.
  void answer(std::span<const Input> inputs, std::span<Answer> out) override;
  std::pair<std::string, std::string> reproducer(const Input& input, Query query, const std::string& exact) override;
  /// `node` with NODE_PATH at the adapter directory's node_modules (the libraries it pinned).
  std::string reproducer_runner() const override;

 private:
  void start();
  void stop();
  /// answer() for inputs that all ask the same (pairs, or points).
  void answer_group(std::span<const Input> inputs, std::span<Answer> out);
  /// Sends a batch and reads its results; false when the adapter timed out or died.
  bool round_trip(std::span<const Input> inputs, std::span<Answer> out, std::chrono::milliseconds timeout);
  void send(char type, const std::string& payload);
  /// Reads one message; false on timeout or end of stream.
  bool receive(char& type, std::string& payload, std::chrono::milliseconds timeout);
  bool read_exact(char* buf, std::size_t n, std::chrono::steady_clock::time_point deadline);

  std::vector<std::string> argv_;
  std::chrono::milliseconds timeout_;
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  Info info_;
};

/// Parses a hello's JSON into Info. Throws AdapterError naming the missing or bad field.
Info parse_hello(const std::string& json);

}  // namespace collide::judge
