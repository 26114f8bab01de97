// Netgames beside Chocolate Doom on this machine's loopback: Debian's chocolate-server
// and chocolate-doom (tools/install-deps.sh installs them) and our game, over a relay
// that loses and delays packets. Real time: each game lasts a few seconds.
#ifdef P3D_GAME
#include <gtest/gtest.h>

#include <chrono>

#include "tests/support/support.h"

namespace p3d {
namespace {

constexpr const char* kServer = "/usr/games/chocolate-server";

int run_netgame_command(const std::string& command, std::string& output) {
  return test::run("cd '" + test::source_dir().string() + "' && " + command, output);
}

void need_chocolate() {
  ASSERT_TRUE(std::filesystem::exists(kServer) && std::filesystem::exists("/usr/games/chocolate-doom"))
      << "Debian's chocolate-doom is missing (tools/install-deps.sh installs it)";
}

// Chocolate Doom leads a co-op game of two and records it; our client plays through a
// relay that loses 5% of the packets and holds each 30 to 60 ms. Both record the same
// commands, and our live game equals the replay of Chocolate's demo, tic for tic.
TEST(Netgame, BesideChocolateDoomThroughALossyRelayEveryTicIsTheReplays) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "real time, not work: the Release build plays it (the sanitizers check the code in memory)";
#endif
  need_chocolate();
  std::string o;
  const int status = run_netgame_command("tools/peers/netgame_peers.sh --game " + std::string(P3D_GAME) +
                                       " --players 2 --tics 140 --drop 0.05 --delay-ms 30",
                                   o);
  EXPECT_EQ(status, 0) << o;
  EXPECT_NE(o.find("client 1: demo = Chocolate, live = replay 140 of 140 tics"), std::string::npos) << o;
}

// A server nobody answers from, and a game of another IWAD: a clear message, soon.
TEST(Netgame, NoServerOrAnotherGameIsSaidAndNeverHangs) {
  need_chocolate();
  const std::string game = P3D_GAME;
  std::string o;
  auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_netgame_command(game + " --iwad /usr/share/games/doom/freedoom2.wad --headless --connect 127.0.0.1:9", o), 1) << o;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 8.0);
  EXPECT_NE(o.find("pseudo3d: netgame on 127.0.0.1:9: no answer from the server"), std::string::npos) << o;

  // The first to join plays Doom II (freedoom2) and waits for a second; a Doom
  // (freedoom1) client is refused.
  const std::string script =
      "port=$(python3 -c \"import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(('127.0.0.1', 0)); "
      "print(s.getsockname()[1])\"); " +
      std::string(kServer) + " -port $port >/dev/null 2>&1 & server=$!; sleep 0.5; " + game +
      " --iwad /usr/share/games/doom/freedoom2.wad --headless --connect 127.0.0.1:$port --nodes 2 >/dev/null 2>&1 & "
      "first=$!; sleep 1; " +
      game + " --iwad /usr/share/games/doom/freedoom1.wad --headless --connect 127.0.0.1:$port 2>&1; status=$?; "
      "kill $first $server; exit $status";
  start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_netgame_command(script, o), 1) << o;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_NE(o.find("the server refused: Game mismatch: server is doom2 (commercial), client is doom (retail)"),
            std::string::npos)
      << o;
}

}  // namespace
}  // namespace p3d
#endif
