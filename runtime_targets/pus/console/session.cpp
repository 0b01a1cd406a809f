// Sending TCs and tabulating what comes back.
#include "console/session.h"

#include <istream>
#include <ostream>

#include "console/hex.h"

namespace smcbip::pus::console {

Session::Session(const Config& config, std::ostream& out, Link* link)
    : config_(config), out_(out), link_(link), table_(table_header() + "\n") {
  out_ << table_ << std::flush;
}

void Session::add(const Row& row) {
  const std::string text = format_row(row) + "\n";
  table_ += text;
  rows_.push_back(row);
  out_ << text << std::flush;
}

void Session::send(const Telecommand& tc, std::span<const std::uint8_t> bytes) {
  if (link_ != nullptr) link_->send(bytes);
  add(tc_row(rows_.size() + 1, tc, config_, link_ != nullptr ? "sent" : "not sent"));
  if (link_ == nullptr) return;
  while (auto packet = link_->receive(std::chrono::milliseconds(0))) received(*packet);
}

void Session::send_raw(std::span<const std::uint8_t> bytes) {
  if (link_ != nullptr) link_->send(bytes);
  const std::size_t index = rows_.size() + 1;
  const std::string status = link_ != nullptr ? "sent" : "not sent";
  auto tc = decode_tc(bytes, config_);
  Row row =
      tc ? tc_row(index, tc.value(), config_, status) : malformed_row(index, bytes, tc.error());
  row.status = status;
  add(row);
  if (link_ == nullptr) return;
  while (auto packet = link_->receive(std::chrono::milliseconds(0))) received(*packet);
}

void Session::receive_for(std::chrono::milliseconds wait) {
  if (link_ == nullptr) return;
  const auto deadline = link_->now() + wait;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - link_->now());
    if (left.count() <= 0) return;
    auto packet = link_->receive(left);
    if (!packet) return;
    received(*packet);
  }
}

void Session::received(std::span<const std::uint8_t> bytes) {
  const std::size_t index = rows_.size() + 1;
  packets_ += to_hex(bytes) + "\n";
  auto packet = decode(bytes, config_);
  add(packet ? packet_row(index, packet.value(), config_)
             : malformed_row(index, bytes, packet.error()));
}

void run_script(const ParsedScript& script, Session& session, std::chrono::milliseconds wait) {
  for (const ParsedScript::Entry& entry : script.tcs) {
    if (entry.wait) {
      session.receive_for(*entry.wait);
    } else if (entry.raw) {
      session.send_raw(entry.bytes);
    } else {
      session.send(entry.tc, entry.bytes);
    }
  }
  if (!script.tcs.empty()) session.receive_for(wait);
}

std::size_t run_interactive(std::istream& in, const std::string& name, Session& session,
                            std::ostream& err, std::chrono::milliseconds wait,
                            const Config& config) {
  Sequencer sequencer;
  std::size_t refused = 0;
  std::string text;
  for (std::uint32_t line = 1; std::getline(in, text); ++line) {
    LineResult result = parse_line(text, line, config);
    for (const ScriptError& e : result.errors) err << format_error(name, e) << "\n";
    refused += result.errors.empty() ? 0 : 1;
    if (result.wait) session.receive_for(*result.wait);
    if (result.raw) {
      session.send_raw(*result.raw);
      session.receive_for(wait);
    }
    if (!result.has_tc) continue;
    sequencer.number(result.tc);
    session.send(result.tc.tc, encode_tc(result.tc.tc, config));
    session.receive_for(wait);
  }
  return refused;
}

std::string format_error(const std::string& name, const ScriptError& error) {
  return name + ":" + std::to_string(error.line) + ":" + std::to_string(error.column) +
         ": error: " + error.message;
}

}  // namespace smcbip::pus::console
