// A console session: TCs sent over a link (or only listed), every TM received decoded into the
// table, the table kept for the log.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "console/link.h"
#include "console/script.h"
#include "console/table.h"
#include "packets/packets.h"

namespace smcbip::pus::console {

/// Numbers the rows of a session, prints each as it comes and keeps them for the log.
class Session {
 public:
  /// Without a link, TCs are listed as "not sent" and nothing is received.
  Session(const Config& config, std::ostream& out, Link* link);

  /// Sends one encoded TC (when there is a link) and adds its row; then adds the rows of the
  /// packets already received.
  void send(const Telecommand& tc, std::span<const std::uint8_t> bytes);
  /// Sends octets as they are (when there is a link) and adds their row: a TC's if they decode
  /// as one, else the decoder's refusal; then adds the rows of the packets already received.
  void send_raw(std::span<const std::uint8_t> bytes);
  /// Adds the row of every packet received until `wait` has passed.
  void receive_for(std::chrono::milliseconds wait);
  /// Adds the row of one packet received (a TM, a TC, or octets the decoder refuses).
  void received(std::span<const std::uint8_t> bytes);

  /// The table so far: the header then one line per row, each ending in a newline.
  const std::string& table() const { return table_; }
  const std::vector<Row>& rows() const { return rows_; }
  /// Every packet received so far, as hex, one a line (what the table decodes, undecoded).
  const std::string& packets() const { return packets_; }

 private:
  void add(const Row& row);

  Config config_;
  std::ostream& out_;
  Link* link_;
  std::string table_;
  std::vector<Row> rows_;
  std::string packets_;
};

/// Sends the TCs of a script in order, receiving during its pauses and, with a link, until
/// `wait` after the last entry.
void run_script(const ParsedScript& script, Session& session, std::chrono::milliseconds wait);

/// Reads TC lines from `in` until its end, as a script's (errors go to `err` as
/// `NAME:LINE:COL: error: ...` and the line is skipped); sends each TC at once and receives
/// for `wait` after it (and for MS on a `wait MS` line). Returns the number of refused lines.
std::size_t run_interactive(std::istream& in, const std::string& name, Session& session,
                            std::ostream& err, std::chrono::milliseconds wait,
                            const Config& config);

/// `NAME:LINE:COL: error: MESSAGE`.
std::string format_error(const std::string& name, const ScriptError& error);

}  // namespace smcbip::pus::console
