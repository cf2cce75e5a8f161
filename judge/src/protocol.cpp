// The subprocess adapter: protocol version 2 over pipes (protocol.hpp, docs/judge.md).

#include "collide/judge/protocol.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace collide::judge {

namespace {

using Clock = std::chrono::steady_clock;

void put_u8(std::string& s, std::uint8_t v) {
  s.push_back(static_cast<char>(v));
}
void put_u16(std::string& s, std::uint16_t v) {
  put_u8(s, v & 0xff);
  put_u8(s, v >> 8);
}
void put_u32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) put_u8(s, (v >> (8 * i)) & 0xff);
}
void put_f64(std::string& s, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  for (int i = 0; i < 8; ++i) put_u8(s, (bits >> (8 * i)) & 0xff);
}
void put_shape(std::string& s, const ShapeData& d) {
  put_u8(s, static_cast<std::uint8_t>(d.kind));
  put_u16(s, static_cast<std::uint16_t>(d.values.size()));
  for (double v : d.values) put_f64(s, v);
}

/// Reads a results payload; every read is bounds-checked (a short payload is a protocol error).
class Reader {
 public:
  explicit Reader(const std::string& s) : s_(s) {}
  std::uint64_t uint(int bytes) {
    need(bytes);
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t(static_cast<unsigned char>(s_[pos_ + i])) << (8 * i);
    pos_ += bytes;
    return v;
  }
  double f64() {
    const std::uint64_t bits = uint(8);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::string text(std::size_t n) {
    need(n);
    std::string t = s_.substr(pos_, n);
    pos_ += n;
    return t;
  }
  ShapeData shape() {
    ShapeData d;
    const auto k = uint(1);
    if (k >= kKindCount - 1) throw AdapterError("protocol: stored shape of unknown kind " + std::to_string(k));
    d.kind = static_cast<ShapeKind>(k);
    const auto n = uint(2);
    for (std::uint64_t i = 0; i < n; ++i) d.values.push_back(f64());
    return d;
  }
  bool done() const { return pos_ == s_.size(); }

 private:
  void need(std::size_t n) const {
    if (pos_ + n > s_.size()) throw AdapterError("protocol: results message ends early");
  }
  const std::string& s_;
  std::size_t pos_ = 0;
};

ShapeKind kind_named(const std::string& s) {
  for (ShapeKind k : kKinds)
    if (name(k) == s && k != ShapeKind::Compound) return k;
  throw AdapterError("hello: unknown kind '" + s + "'");
}

std::string bits_hex(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, 8);
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(b));
  return buf;
}

}  // namespace

Info parse_hello(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw AdapterError(std::string("hello: not JSON: ") + e.what());
  }
  auto field = [&](const nlohmann::json& o, const char* key) -> const nlohmann::json& {
    if (!o.contains(key)) throw AdapterError(std::string("hello: missing field '") + key + "'");
    return o.at(key);
  };
  if (field(j, "protocol") != kProtocolVersion)
    throw AdapterError("hello: protocol " + field(j, "protocol").dump() + ", the judge speaks " +
                       std::to_string(kProtocolVersion));
  Info info;
  try {
    info.library = field(j, "library").get<std::string>();
    info.version = field(j, "version").get<std::string>();
    for (const auto& k : field(j, "kinds")) info.kinds.push_back(kind_named(k.get<std::string>()));
    for (const auto& q : field(j, "queries")) {
      const std::string s = q.get<std::string>();
      if (s == "overlap")
        info.queries.push_back(Query::Overlap);
      else if (s == "push")
        info.queries.push_back(Query::Push);
      else if (s == "contains")
        info.queries.push_back(Query::Contains);
      else
        throw AdapterError("hello: unknown query '" + s + "'");
    }
    const auto& c = field(j, "contract");
    info.contract.scalar = field(c, "scalar").get<std::string>();
    if (info.contract.scalar != "float32" && info.contract.scalar != "float64")
      throw AdapterError("hello: scalar must be float32 or float64");
    const std::string t = field(c, "touching").get<std::string>();
    info.contract.touching = t == "overlap"  ? Touching::Overlap
                             : t == "apart"  ? Touching::Apart
                             : t == "either" ? Touching::Either
                                             : throw AdapterError("hello: touching must be overlap, apart or either");
    info.contract.tol_abs = field(c, "tol_abs").get<double>();
    info.contract.tol_rel = field(c, "tol_rel").get<double>();
    const std::string m = field(c, "push_moves").get<std::string>();
    if (m != "a" && m != "b") throw AdapterError("hello: push_moves must be a or b");
    info.contract.push_moves = m == "a" ? PushMoves::A : PushMoves::B;
    info.contract.source = field(c, "source").get<std::string>();
    info.contract.min_size = c.value("min_size", 0.0);
    info.contract.max_size = c.value("max_size", 0.0);
    if (c.contains("contains")) {
      const auto& pc = c.at("contains");
      if (pc.contains("touching")) {
        const std::string pt = pc.at("touching").get<std::string>();
        info.contract.contains_touching =
            pt == "overlap"  ? Touching::Overlap
            : pt == "apart"  ? Touching::Apart
            : pt == "either" ? Touching::Either
                             : throw AdapterError("hello: contains.touching must be overlap, apart or either");
      }
      if (pc.contains("tol_abs")) info.contract.contains_tol_abs = pc.at("tol_abs").get<double>();
    }
    info.mapping = field(j, "mapping").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw AdapterError(std::string("hello: bad field: ") + e.what());
  }
  if (info.kinds.empty()) throw AdapterError("hello: no kinds");
  if (info.queries.empty() || info.queries.front() != Query::Overlap)
    throw AdapterError("hello: queries must start with overlap");
  return info;
}

Subprocess::Subprocess(std::vector<std::string> argv, std::chrono::milliseconds timeout)
    : argv_(std::move(argv)), timeout_(timeout) {
  if (argv_.empty()) throw AdapterError("no adapter command");
  std::signal(SIGPIPE, SIG_IGN);  // a dead adapter must show as an error on write, not kill the judge
  start();
}

Subprocess::~Subprocess() {
  stop();
}

void Subprocess::start() {
  int in[2], out[2];
  if (pipe(in) != 0 || pipe(out) != 0) throw AdapterError("pipe: " + std::string(std::strerror(errno)));
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  for (int fd : {in[0], in[1], out[0], out[1]}) posix_spawn_file_actions_addclose(&fa, fd);
  std::vector<char*> args;
  for (std::string& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  const int rc = posix_spawnp(&pid_, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(in[0]);
  close(out[1]);
  to_child_ = in[1];
  from_child_ = out[0];
  if (rc != 0) {
    stop();
    throw AdapterError("cannot start " + argv_[0] + ": " + std::strerror(rc));
  }
  char type = 0;
  std::string payload;
  if (!receive(type, payload, std::max(timeout_, std::chrono::milliseconds(30000))) || type != 'H') {
    stop();
    throw AdapterError("adapter '" + argv_[0] + (argv_.size() > 1 ? " " + argv_[1] : std::string()) +
                       "' sent no hello (is its library installed? run npm ci in judge/js)");
  }
  info_ = parse_hello(payload);
}

void Subprocess::stop() {
  if (to_child_ >= 0) close(to_child_);
  if (from_child_ >= 0) close(from_child_);
  to_child_ = from_child_ = -1;
  if (pid_ > 0) {
    // Closed stdin ends a healthy adapter; one that does not exit promptly is killed.
    for (int i = 0; i < 50; ++i) {
      if (waitpid(pid_, nullptr, WNOHANG) == pid_) {
        pid_ = -1;
        return;
      }
      usleep(2000);
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
}

void Subprocess::send(char type, const std::string& payload) {
  std::string msg;
  put_u32(msg, static_cast<std::uint32_t>(payload.size() + 1));
  msg.push_back(type);
  msg += payload;
  std::size_t off = 0;
  while (off < msg.size()) {
    const ssize_t w = write(to_child_, msg.data() + off, msg.size() - off);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw AdapterError("adapter closed its input");
    off += static_cast<std::size_t>(w);
  }
}

bool Subprocess::read_exact(char* buf, std::size_t n, Clock::time_point deadline) {
  std::size_t got = 0;
  while (got < n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{from_child_, POLLIN, 0};
    const int r = poll(&p, 1, static_cast<int>(left));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    const ssize_t k = read(from_child_, buf + got, n - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    got += static_cast<std::size_t>(k);
  }
  return true;
}

bool Subprocess::receive(char& type, std::string& payload, std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  unsigned char len[4];
  if (!read_exact(reinterpret_cast<char*>(len), 4, deadline)) return false;
  const std::uint32_t n = len[0] | (len[1] << 8) | (len[2] << 16) | (std::uint32_t(len[3]) << 24);
  if (n == 0 || n > (1u << 30)) throw AdapterError("protocol: message length " + std::to_string(n));
  std::string body(n, '\0');
  if (!read_exact(body.data(), n, deadline)) return false;
  type = body[0];
  payload = body.substr(1);
  return true;
}

bool Subprocess::round_trip(std::span<const Input> inputs, std::span<Answer> out, std::chrono::milliseconds timeout) {
  // Every input of one call asks the same: pairs go in a 'B' batch, points in a 'C' batch.
  const bool points = !inputs.empty() && inputs.front().ask == Query::Contains;
  std::string batch;
  put_u32(batch, static_cast<std::uint32_t>(inputs.size()));
  for (const Input& in : inputs) {
    put_shape(batch, in.a);
    if (points) {
      put_f64(batch, in.p.x());
      put_f64(batch, in.p.y());
    } else {
      put_shape(batch, in.b);
    }
  }
  try {
    send(points ? 'C' : 'B', batch);
  } catch (const AdapterError&) {
    return false;
  }
  char type = 0;
  std::string payload;
  if (!receive(type, payload, timeout)) return false;
  if (type != 'R') throw AdapterError(std::string("protocol: expected results, got message type '") + type + "'");
  Reader r(payload);
  if (r.uint(4) != inputs.size()) throw AdapterError("protocol: results count differs from the batch's");
  for (Answer& a : out) {
    a = Answer{};
    const auto status = r.uint(1);
    if (status > 2) throw AdapterError("protocol: unknown status " + std::to_string(status));
    a.status = static_cast<Status>(status);
    if (a.status == Status::Ok && points) {
      a.contains = r.uint(1) != 0;
      a.stored_a = r.shape();
      const double px = r.f64(), py = r.f64();
      a.stored_p = Vec2<double>(px, py);
    } else if (a.status == Status::Ok) {
      a.overlap = r.uint(1) != 0;
      a.has_push = r.uint(1) != 0;
      const double px = r.f64(), py = r.f64();
      a.push = Vec2<double>(px, py);
      a.stored_a = r.shape();
      a.stored_b = r.shape();
    } else if (a.status == Status::Threw) {
      a.error = r.text(r.uint(2));
    }
  }
  if (!r.done()) throw AdapterError("protocol: trailing bytes after the results");
  return true;
}

void Subprocess::answer(std::span<const Input> inputs, std::span<Answer> out) {
  // Pairs and points travel in messages of their own; each group keeps its inputs' order.
  std::vector<std::size_t> groups[2];
  for (std::size_t i = 0; i < inputs.size(); ++i) groups[inputs[i].ask == Query::Contains].push_back(i);
  for (const auto& g : groups) {
    if (g.size() == inputs.size()) {
      answer_group(inputs, out);
      return;
    }
    if (g.empty()) continue;
    std::vector<Input> in;
    in.reserve(g.size());
    for (std::size_t i : g) in.push_back(inputs[i]);
    std::vector<Answer> got(g.size());
    answer_group(in, got);
    for (std::size_t k = 0; k < g.size(); ++k) out[g[k]] = std::move(got[k]);
  }
}

void Subprocess::answer_group(std::span<const Input> inputs, std::span<Answer> out) {
  const auto batch_timeout = timeout_ + std::chrono::milliseconds(2 * inputs.size());
  if (round_trip(inputs, out, batch_timeout)) return;
  // Isolate the input that hung or killed the adapter: a fresh process, one input at a time
  // (restarted after each input that fails).
  stop();
  start();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (round_trip(inputs.subspan(i, 1), out.subspan(i, 1), timeout_)) continue;
    const bool died = waitpid(pid_, nullptr, WNOHANG) == pid_;
    if (died) pid_ = -1;
    out[i] = Answer{};
    out[i].status = died ? Status::Threw : Status::Hung;
    out[i].error = died ? "adapter died on this input" : "hang: no answer within the time-out";
    stop();
    start();
  }
}

std::string Subprocess::reproducer_runner() const {
  const std::string script = argv_.size() > 1 ? argv_[1] : std::string();
  const std::size_t slash = script.rfind('/');
  const std::string dir = slash == std::string::npos ? std::string(".") : script.substr(0, slash);
  return "env NODE_PATH='" + dir + "/node_modules' " + argv_[0];
}

std::pair<std::string, std::string> Subprocess::reproducer(const Input& input, Query query, const std::string& exact) {
  auto shape_json = [](const ShapeData& d) {
    nlohmann::json bits = nlohmann::json::array();
    for (double v : d.values) bits.push_back(bits_hex(v));
    return nlohmann::json{{"kind", std::string(name(d.kind))}, {"bits", bits}};
  };
  nlohmann::json req = {{"query", std::string(name(query))}, {"exact", exact}, {"a", shape_json(input.a)}};
  if (input.ask == Query::Contains)
    req["p"] = {bits_hex(input.p.x()), bits_hex(input.p.y())};
  else
    req["b"] = shape_json(input.b);
  send('P', req.dump());
  char type = 0;
  std::string payload;
  if (!receive(type, payload, std::max(timeout_, std::chrono::milliseconds(10000))) || type != 'S')
    throw AdapterError("adapter sent no reproducer source");
  const nlohmann::json s = nlohmann::json::parse(payload);
  return {s.at("ext").get<std::string>(), s.at("source").get<std::string>()};
}

}  // namespace collide::judge
