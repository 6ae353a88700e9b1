// tv-replay --listen: a headless receiver of a live stream. It waits for one game, writes its
// stream to a file as it arrives (every chunk checked first, flushed), and exits when the game
// disconnects or after --frames N. The file is a recording tv-replay --validate checks.

#include "listen.hpp"

#include <cstdio>
#include <iostream>

#include "tv/app/user_message.hpp"
#include "tv/record/live.hpp"

namespace tv::replay {

int listen(const ListenOptions& o) {
  LiveReceiverOptions ro;
  ro.address = o.address;
  ro.saveTo = o.out;
  ro.stopAfterFrames = o.frames;
  ro.keepBytes = std::uint64_t{16} << 20;  // the file keeps the run; memory only a little
  try {
    LiveReceiver rx(ro);
    std::printf("listening on %s\n", rx.address().c_str());
    std::fflush(stdout);  // a script waits for this line to learn the port
    double waited = 0.0;
    bool connected = false;
    for (;;) {
      if (!rx.wait(0.25)) {
        waited += 0.25;
        if (!connected && o.waitSeconds > 0 && waited >= o.waitSeconds) {
          std::cerr << "tv-replay: no game connected to " << rx.address() << " within "
                    << o.waitSeconds << " s\n";
          return 1;
        }
        continue;
      }
      for (const LiveEvent& e : rx.poll()) {
        switch (e.kind) {
          case LiveEvent::Kind::connected:
            connected = true;
            std::printf("%s\n", e.text.c_str());
            std::fflush(stdout);
            break;
          case LiveEvent::Kind::frames:
          case LiveEvent::Kind::dropped:
          case LiveEvent::Kind::control:
            break;
          case LiveEvent::Kind::ended:
            std::printf("%s\nsaved %llu frames into %s\n", e.text.c_str(),
                        static_cast<unsigned long long>(e.frame), o.out.c_str());
            return 0;
          case LiveEvent::Kind::refused:
            std::cerr << "tv-replay: " << e.text << "\n";
            if (e.run != 0 && !rx.window().connected && connected) {
              std::cerr << "tv-replay: " << o.out << " holds the whole frames before that\n";
              return 1;
            }
            break;
        }
      }
    }
  } catch (const Error& e) {
    std::cerr << "tv-replay: --listen " << o.address << ": " << app::userMessage(e) << "\n";
    return 2;
  }
}

}  // namespace tv::replay
