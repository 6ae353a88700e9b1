#pragma once
// tv-replay --listen [HOST:]PORT --out FILE [--frames N] [--wait S] (listen.cpp).

#include <cstdint>
#include <string>

namespace tv::replay {

struct ListenOptions {
  std::string address;       // [HOST:]PORT; host 127.0.0.1 unless given
  std::string out;           // where the stream is saved
  std::uint64_t frames = 0;  // stop after this many (0: when the game disconnects)
  double waitSeconds = 0;    // give up when no game connects within this (0: wait forever)
};

// Exit status: 0 the run was received (the game closed it, disconnected, or N frames came),
// 1 no game came in time or the stream was refused as malformed, 2 a bad address or file.
int listen(const ListenOptions& o);

}  // namespace tv::replay
