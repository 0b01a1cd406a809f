// pus-console over UDP on the loopback: a responder in the test answers TC[17,1] with TM[1,1],
// TM[17,2] and TM[1,7] built by the packet library, and the session tabulates them.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bipc/errors.h"
#include "console/console.h"
#include "console_test_support.h"

namespace smcbip::pus::console {
namespace {

using testing::verification;

/// A UDP socket on 127.0.0.1 at a port the system chooses; answers each TC[17,1] it receives
/// with TM[1,1], TM[17,2], TM[1,7], each TC of another type with TM[1,2] (code 1).
class Responder {
 public:
  Responder() {
    socket_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    EXPECT_EQ(::bind(socket_, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    socklen_t size = sizeof address;
    EXPECT_EQ(::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &size), 0);
    port_ = ntohs(address.sin_port);
  }
  ~Responder() { ::close(socket_); }

  std::uint16_t port() const { return port_; }
  const std::vector<std::vector<std::uint8_t>>& received() const { return received_; }
  void stop() { stop_ = true; }

  /// Answers the TCs that arrive until stop() (or 20 s, should a test forget to stop it).
  void serve() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!stop_ && std::chrono::steady_clock::now() < deadline) {
      pollfd ready{socket_, POLLIN, 0};
      if (::poll(&ready, 1, 20) <= 0) continue;
      std::vector<std::uint8_t> bytes(4096);
      sockaddr_in from{};
      socklen_t size = sizeof from;
      const ssize_t got = ::recvfrom(socket_, bytes.data(), bytes.size(), 0,
                                     reinterpret_cast<sockaddr*>(&from), &size);
      if (got <= 0) continue;
      bytes.resize(static_cast<std::size_t>(got));
      received_.push_back(bytes);
      answer(bytes, from);
    }
  }

 private:
  void answer(const std::vector<std::uint8_t>& bytes, const sockaddr_in& to) {
    auto tc = decode_tc(bytes, Config{});
    if (!tc) return;
    const RequestId request = RequestId::of(tc.value().primary);
    if (tc.value().header.service == 17 && tc.value().header.subtype == 1) {
      reply(1, 1, verification(request), to);
      reply(17, 2, NoData{}, to);
      reply(1, 7, verification(request), to);
    } else {
      reply(1, 2, verification(request, 0, 1), to);
    }
  }

  void reply(std::uint8_t service, std::uint8_t subtype, Message data, const sockaddr_in& to) {
    Telemetry tm;
    tm.primary.apid = 0x12;
    tm.primary.sequence_count = tm_count_++;
    tm.header.service = service;
    tm.header.subtype = subtype;
    tm.header.message_type_counter = tm_count_;
    tm.header.time = CucTime{10, 0};
    tm.data = std::move(data);
    std::vector<std::uint8_t> out(512);
    auto length = encode(tm, Config{}, out);
    ASSERT_TRUE(length.ok());
    ::sendto(socket_, out.data(), length.value(), 0, reinterpret_cast<const sockaddr*>(&to),
             sizeof to);
  }

  int socket_ = -1;
  std::uint16_t port_ = 0;
  std::uint16_t tm_count_ = 0;
  std::atomic<bool> stop_ = false;
  std::vector<std::vector<std::uint8_t>> received_;
};

std::vector<std::string> informations(const Session& session) {
  std::vector<std::string> out;
  for (const Row& row : session.rows()) out.push_back(row.status + " " + row.information);
  return out;
}

TEST(PusConsoleUdp, AConnectionTestIsAnsweredAndTabulated) {
  Responder responder;
  std::thread server([&] { responder.serve(); });
  const ParsedScript script = parse_script("17 1 --apid 0x12 --seq 5\n", Config{});
  std::ostringstream out;
  {
    UdpLink link("127.0.0.1", responder.port());
    Session session(Config{}, out, &link);
    run_script(script, session, std::chrono::milliseconds(1000));
    EXPECT_EQ(informations(session),
              (std::vector<std::string>{"sent TC[17,1] are-you-alive connection test",
                                        "ok TM[1,1] acceptance success of TC apid 0x12 seq 5",
                                        "ok TM[17,2] are-you-alive connection test report",
                                        "ok TM[1,7] completion success of TC apid 0x12 seq 5"}));
    if (session.rows().size() == 4) {
      EXPECT_EQ(format_row(session.rows()[2]),
                "3     TM  17   2    10.000        0x12   0      1      ok        "
                "TM[17,2] are-you-alive connection test report");
    }
    EXPECT_EQ(out.str(), session.table());
  }
  responder.stop();
  server.join();
  ASSERT_EQ(responder.received().size(), 1u);
  EXPECT_EQ(responder.received()[0], script.tcs[0].bytes);
}

TEST(PusConsoleUdp, InteractiveLinesAreSentAsTheyComeAndBadOnesReported) {
  Responder responder;
  std::thread server([&] { responder.serve(); });
  std::istringstream in("17 1 --apid 0x12\n17 1 --rate 3\n20 1 --param 7\n");
  std::ostringstream out, err;
  {
    UdpLink link("127.0.0.1", responder.port());
    Session session(Config{}, out, &link);
    const std::size_t refused =
        run_interactive(in, "<stdin>", session, err, std::chrono::milliseconds(300), Config{});
    EXPECT_EQ(refused, 1u);
    EXPECT_EQ(informations(session),
              (std::vector<std::string>{
                  "sent TC[17,1] are-you-alive connection test",
                  "ok TM[1,1] acceptance success of TC apid 0x12 seq 0",
                  "ok TM[17,2] are-you-alive connection test report",
                  "ok TM[1,7] completion success of TC apid 0x12 seq 0",
                  "sent TC[20,1] report parameter values: parameters 7",
                  "failure TM[1,2] acceptance failure of TC apid 0x0 seq 0, code 1"}));
  }
  responder.stop();
  server.join();
  EXPECT_EQ(err.str().rfind("<stdin>:2:6: error: --rate: TC[17,1]", 0), 0u) << err.str();
}

std::string read_all(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// A pause lets the answers to the first TC in before the second is sent.
TEST(PusConsoleUdp, AWaitLineReceivesBeforeTheNextTc) {
  Responder responder;
  std::thread server([&] { responder.serve(); });
  const ParsedScript script =
      parse_script("17 1 --apid 0x12\nwait 500\n20 1 --param 7\n", Config{});
  std::ostringstream out;
  {
    UdpLink link("127.0.0.1", responder.port());
    Session session(Config{}, out, &link);
    run_script(script, session, std::chrono::milliseconds(500));
    EXPECT_EQ(informations(session),
              (std::vector<std::string>{
                  "sent TC[17,1] are-you-alive connection test",
                  "ok TM[1,1] acceptance success of TC apid 0x12 seq 0",
                  "ok TM[17,2] are-you-alive connection test report",
                  "ok TM[1,7] completion success of TC apid 0x12 seq 0",
                  "sent TC[20,1] report parameter values: parameters 7",
                  "failure TM[1,2] acceptance failure of TC apid 0x0 seq 0, code 1"}));
  }
  responder.stop();
  server.join();
}

// The executable itself: a script sent over UDP, the table on stdout and the same in the log.
TEST(PusConsoleUdp, TheExecutableRunsAScriptAndLogsTheTable) {
  char folder[] = "/tmp/pus_console_XXXXXX";
  ASSERT_NE(::mkdtemp(folder), nullptr);
  const std::string script = std::string(folder) + "/ping.tc", log = std::string(folder) + "/log",
                    packets = std::string(folder) + "/packets";
  std::ofstream(script) << "# ping\n17 1 --apid 0x12 --seq 7\n";
  Responder responder;
  std::thread server([&] { responder.serve(); });
  const std::string command = std::string(PUS_CONSOLE_PATH) + " script " + script + " --port " +
                              std::to_string(responder.port()) + " --wait 800 --log " + log +
                              " --packet-log " + packets;
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  for (int c; pipe != nullptr && (c = std::fgetc(pipe)) != EOF;) out += static_cast<char>(c);
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  responder.stop();
  server.join();
  EXPECT_EQ(status, 0);
  EXPECT_EQ(read_all(log), out);
  EXPECT_NE(out.find("1     TC  17   1    -             0      0x12   7      sent      "),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("ok        TM[1,1] acceptance success of TC apid 0x12 seq 7\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("\n3     TM  17   2    "), std::string::npos) << out;
  EXPECT_NE(out.find("\n4     TM  1    7    10.000        0x12   0      2      ok        "
                     "TM[1,7] completion success of TC apid 0x12 seq 7\n"),
            std::string::npos)
      << out;
  // The packet log: the three TMs received, one a line, each the octets the table decodes.
  std::istringstream lines(read_all(packets));
  std::vector<std::string> received;
  for (std::string line; std::getline(lines, line);) received.push_back(line);
  ASSERT_EQ(received.size(), 3u);
  for (std::size_t i = 0; i < received.size(); ++i) {
    std::vector<std::uint8_t> bytes;
    HexError error;
    ASSERT_TRUE(parse_hex(received[i], bytes, error)) << received[i];
    const Row row = decode_bytes(bytes, Config{});
    EXPECT_NE(out.find(row.information), std::string::npos) << row.information;
  }
  std::remove(script.c_str());
  std::remove(log.c_str());
  std::remove(packets.c_str());
  ::rmdir(folder);
}

TEST(PusConsoleUdp, MalformedDatagramsBecomeMalformedRows) {
  std::ostringstream out;
  Session session(Config{}, out, nullptr);
  session.received(std::vector<std::uint8_t>{0x08, 0x12, 0xC0});
  EXPECT_EQ(session.packets(), "0812c0\n");  // kept as received, for --packet-log
  ASSERT_EQ(session.rows().size(), 1u);
  EXPECT_EQ(session.rows()[0].status, "malformed");
  EXPECT_EQ(session.rows()[0].information.rfind("too-short at byte ", 0), 0u)
      << session.rows()[0].information;
}

TEST(PusConsoleUdp, AHostThatIsNotAnAddressIsRefused) {
  EXPECT_THROW(UdpLink("localhost", 1), smcbip::UsageError);
}

}  // namespace
}  // namespace smcbip::pus::console
