// The simulation driver: determinism is a number (the state hash), at any render rate, through
// any number of steps back; tracing watches without touching.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

constexpr std::uint64_t kTicks = 120;

// Small but busy versions of every scene, so that every mover on every scene stays cheap.
Params quick(const SceneDef& s) {
  Params p = s.defaults();
  if (s.name == "bullets-wall") p.set(param::count, 100);
  if (s.name == "crowd") p.set(param::count, 60);
  if (s.name == "bump-crowd") p.set(param::count, 100);
  return p;
}

// A deterministic jitter in [1 - a, 1 + a): the same frame times every run, no <random>.
struct Jitter {
  std::uint64_t s;
  double next(double amount) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const double u = static_cast<double>(s >> 11) * 0x1.0p-53;
    return 1.0 + amount * (2.0 * u - 1.0);
  }
};

// [SECTION] determinism ---------------------------------------------------------------------------

TEST(Determinism, EverySceneAndMoverGivesTheSameHashInTwoInstances) {
  for (const SceneDef& s : builtinScenes().all()) {
    for (const std::string_view m : moverNames()) {
      Simulation a(s, quick(s), parseMover(m));
      Simulation b(s, quick(s), parseMover(m));
      for (std::uint64_t t = 0; t < kTicks; ++t) {
        a.tick();
        b.tick();
      }
      EXPECT_EQ(a.stateHash(), b.stateHash()) << s.name << " / " << m;
      EXPECT_EQ(a.world().stateHash(), b.world().stateHash()) << s.name << " / " << m;
      EXPECT_EQ(a.counters(), b.counters()) << s.name << " / " << m;
      // And a restart replays the same run.
      const std::uint64_t first = a.stateHash();
      a.restart();
      for (std::uint64_t t = 0; t < kTicks; ++t) a.tick();
      EXPECT_EQ(a.stateHash(), first) << s.name << " / " << m;
    }
  }
}

TEST(Determinism, TheHashSeesPositionsVelocitiesCountersAndTheTick) {
  Simulation a("bounce-gap", "continuous");
  Simulation b("bounce-gap", "continuous");
  EXPECT_EQ(a.stateHash(), b.stateHash());
  a.tick();
  EXPECT_NE(a.stateHash(), b.stateHash());
  Params other = b.params();
  other.set(param::seed, 2);
  b.restart(other);
  b.tick();
  EXPECT_NE(a.stateHash(), b.stateHash());
}

TEST(Determinism, TheSameTicksAtAnyRenderRateWithJitteredFrames) {
  // 30, 60, 144, 240 and 360 Hz, each frame ±40% (seeded): the accumulator decides how many
  // ticks each frame runs, and after the same number of ticks the state is the same.
  for (const SceneDef& s : builtinScenes().all()) {
    for (const std::string_view m : {"continuous", "pixel", "discrete"}) {
      Simulation reference(s, quick(s), parseMover(m));
      for (std::uint64_t t = 0; t < kTicks; ++t) reference.tick();
      for (const double hz : {30.0, 60.0, 144.0, 240.0, 360.0}) {
        Simulation sim(s, quick(s), parseMover(m));
        Jitter jitter{static_cast<std::uint64_t>(hz)};
        while (sim.ticks() < kTicks) (void)sim.frame(jitter.next(0.4) / hz);
        if (sim.ticks() > kTicks) sim.seek(kTicks);  // the last frame ran past: step back to it
        EXPECT_EQ(sim.stateHash(), reference.stateHash()) << s.name << " / " << m << " @" << hz;
        EXPECT_EQ(sim.world().stateHash(), reference.world().stateHash()) << s.name << " @" << hz;
      }
    }
  }
}

// [SECTION] fixed step and interpolation ----------------------------------------------------------

TEST(FrameDriver, RunsTicksForTheTimeThatPassedAndInterpolatesTheRest) {
  //   tick:     0             1             2
  //   time:     |-------------|-------------|---
  //   frames:   |-- 0.5 --|---- 1.0 ----^          1.5 ticks of time: one tick runs, and the
  //                                                frame is drawn halfway from tick 0 to tick 1
  Simulation sim("bounce-gap", "continuous");
  const double dt = sim.dt();
  const Vec2 start = sim.bodies()[0].rect.position();
  EXPECT_EQ(sim.frame(dt * 0.5), 0);
  EXPECT_EQ(sim.renderPosition(0), start);
  EXPECT_EQ(sim.frame(dt * 1.0), 1);
  EXPECT_EQ(sim.ticks(), 1u);
  EXPECT_NEAR(sim.alpha(), 0.5, 1e-9);
  const Vec2 now = sim.bodies()[0].rect.position();
  EXPECT_NE(now, start);
  EXPECT_EQ(sim.renderPosition(0), interpolate(start, now, sim.alpha()));
  EXPECT_EQ(sim.renderRect(0).size(), sim.bodies()[0].rect.size());
}

TEST(FrameDriver, ALongHitchRunsAtMostMaxFrameTimeOfTicks) {
  Simulation sim("rest-floor", "continuous");
  const int n = sim.frame(10.0);  // a 10 s hitch: capped at 0.25 s = 15 ticks at 60 Hz
  EXPECT_EQ(n, 15);
  EXPECT_EQ(sim.fixedStep().clampedFrames(), 1u);
}

// [SECTION] snapshots -----------------------------------------------------------------------------

TEST(Snapshots, StepBackAndSeekRestoreTheExactHash) {
  for (const SceneDef& s : builtinScenes().all()) {
    for (const std::string_view m : {"continuous", "pixel", "substep-discrete"}) {
      SimConfig config;
      config.snapshotCapacity = 64;
      Simulation sim(s, quick(s), parseMover(m), config);
      std::vector<std::uint64_t> hash{sim.stateHash()}, world{sim.world().stateHash()};
      for (int t = 0; t < 200; ++t) {
        sim.tick();
        hash.push_back(sim.stateHash());
        world.push_back(sim.world().stateHash());
      }
      const std::string what = s.name + " / " + std::string(m);
      EXPECT_EQ(sim.oldestTick(), 137u) << what;  // 64 ticks, counting the current one
      sim.stepBack();
      EXPECT_EQ(sim.ticks(), 199u);
      EXPECT_EQ(sim.stateHash(), hash[199]) << what;
      sim.seek(150);
      EXPECT_EQ(sim.stateHash(), hash[150]) << what;
      EXPECT_EQ(sim.world().stateHash(), world[150]) << what;
      for (const Body& b : sim.bodies()) EXPECT_EQ(sim.world().rect(b.item), b.rect) << what;
      sim.seek(190);  // forward, still in the ring
      EXPECT_EQ(sim.stateHash(), hash[190]) << what;
      sim.seek(140);
      for (int t = 140; t < 200; ++t) sim.tick();  // replaying from the past reaches the same end
      EXPECT_EQ(sim.stateHash(), hash[200]) << what;
      EXPECT_EQ(sim.world().stateHash(), world[200]) << what;
      // Past the newest snapshot: ticks forward to it.
      Simulation longer(s, quick(s), parseMover(m));
      for (int t = 0; t < 230; ++t) longer.tick();
      sim.seek(230);
      EXPECT_EQ(sim.stateHash(), longer.stateHash()) << what;
    }
  }
}

TEST(Snapshots, ATickThatLeftTheRingIsRefusedNamingTheRange) {
  Simulation sim(findScene("crowd"), quick(findScene("crowd")), {}, {16, 0.25});
  for (int t = 0; t < 40; ++t) sim.tick();
  const std::uint64_t hash = sim.stateHash();
  try {
    sim.seek(3);
    FAIL() << "expected tv::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("tick 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("25..40"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sim.stateHash(), hash);
  Simulation fresh("crowd", "continuous");
  EXPECT_FALSE(fresh.canStepBack());
  EXPECT_THROW(fresh.stepBack(), Error);
}

TEST(Snapshots, AfterAStepBackTheNextTickReplacesTheFuture) {
  Simulation sim("platformer", "continuous");
  for (int t = 0; t < 10; ++t) sim.tick();
  sim.seek(5);
  EXPECT_EQ(sim.newestTick(), 10u);  // still there to seek to
  sim.tick();
  EXPECT_EQ(sim.newestTick(), 6u);
  sim.stepBack();
  EXPECT_EQ(sim.ticks(), 5u);
}

// [SECTION] tracing -------------------------------------------------------------------------------

// A tick whose moves throw part way — here dt = 1e300 makes the falling bodies' goals
// infinite after gravity has been added to their velocities — is undone: same hash, same
// velocities, same render interpolation, and the next good tick is the one it would have been.
TEST(Snapshots, ATickThatThrowsChangesNothing) {
  Simulation sim("rest-floor", "continuous");
  sim.tick();
  Simulation twin("rest-floor", "continuous");
  twin.tick();
  const std::uint64_t before = sim.stateHash();
  const Vec2 velocity = sim.bodies()[0].velocity;
  EXPECT_THROW(sim.tick(1e300), tv::Error);
  EXPECT_EQ(sim.stateHash(), before);
  EXPECT_EQ(sim.bodies()[0].velocity, velocity);
  EXPECT_EQ(sim.ticks(), 1u);
  sim.tick();
  twin.tick();
  EXPECT_EQ(sim.stateHash(), twin.stateHash());
}

// Candidates per move is a mean over the traced moves; stepping back and replaying ticks must
// not count the replayed moves twice.
TEST(Snapshots, SteppingBackAndForthDoesNotRecountTracedMoves) {
  Simulation sim("crowd", "continuous");  // body 0 moves every tick
  sim.traceBody(0);
  for (int t = 0; t < 5; ++t) sim.tick();
  const TraceStats atFive = sim.traceStats();
  ASSERT_EQ(atFive.moves, 5u);
  sim.seek(2);
  EXPECT_EQ(sim.traceStats().moves, 2u);
  sim.seek(5);
  EXPECT_EQ(sim.traceStats().moves, 5u);
  EXPECT_EQ(sim.traceStats().candidates, atFive.candidates);
}

TEST(Tracing, IsOffByDefaultAndNeverChangesResults) {
  for (const SceneDef& s : builtinScenes().all()) {
    for (const std::string_view m : moverNames()) {
      Simulation plain(s, quick(s), parseMover(m));
      Simulation traced(s, quick(s), parseMover(m));
      EXPECT_FALSE(plain.tracedBody().has_value());
      traced.traceBody(0);
      for (int t = 0; t < 60; ++t) {
        plain.tick();
        traced.tick();
      }
      EXPECT_EQ(plain.lastTrace(), nullptr);
      EXPECT_EQ(plain.stateHash(), traced.stateHash()) << s.name << " / " << m;
      // A corner-corrected body (corner-nudge) moves by tv::moveCornered, which keeps no trace:
      // it is drawn where it went, without the move's story.
      const bool cornered = traced.bodies()[0].maxNudge > 0.0;
      if (kTraceCompiledIn && !cornered) {
        EXPECT_GT(traced.traceStats().moves, 0u) << s.name << " / " << m;
      } else if (cornered) {
        EXPECT_EQ(traced.traceStats().moves, 0u) << s.name << " / " << m;
      }
    }
  }
}

TEST(Tracing, RecordsTheSelectedBodysMoveEachTick) {
  Simulation sim("crowd", "continuous");
  sim.traceBody(3);
  sim.tick();
  const MoveTrace* trace = sim.lastTrace();
  ASSERT_NE(trace, nullptr);
  EXPECT_EQ(trace->item, sim.bodies()[3].item);
  EXPECT_EQ(trace->mover, "continuous");
  if constexpr (kTraceCompiledIn) {
    EXPECT_EQ(trace->final, sim.bodies()[3].rect.position());
    EXPECT_EQ(sim.traceStats().moves, 1u);
    EXPECT_EQ(sim.traceStats().candidates, trace->candidates.size());
  }
  sim.traceBody(std::nullopt);
  sim.tick();
  EXPECT_EQ(sim.lastTrace(), nullptr);
}

// [SECTION] velocity responses --------------------------------------------------------------------

Collision hit(ResponseId r, Vec2 normal) {
  Collision c;
  c.response = r;
  c.normal = normal;
  return c;
}

TEST(VelocityResponse, SlideZeroesTheNormalComponentBounceReflectsItTouchStops) {
  //        v = (3, 4), falling to the right
  //          o
  //            `-->
  //   ==============  floor: normal (0, -1), pointing up at the body
  const Vec2 v{3, 4};
  const Vec2 up{0, -1};
  EXPECT_EQ(respondVelocity(v, hit(response::slide, up)), (Vec2{3, 0}));
  EXPECT_EQ(respondVelocity(v, hit(response::bounce, up)), (Vec2{3, -4}));
  EXPECT_EQ(respondVelocity(v, hit(response::touch, up)), (Vec2{0, 0}));
  EXPECT_EQ(respondVelocity(v, hit(response::cross, up)), v);
}

TEST(VelocityResponse, AComponentAlreadyLeavingIsKept) {
  // Pushed out of a floor while already rising: the rise is not undone or reflected.
  const Vec2 rising{3, -4};
  EXPECT_EQ(respondVelocity(rising, hit(response::slide, {0, -1})), rising);
  EXPECT_EQ(respondVelocity(rising, hit(response::bounce, {0, -1})), rising);
}

TEST(VelocityResponse, BouncesBetweenTwoWallsInOneMoveReflectTwice) {
  //   |#|  <- o ->  |#|   right wall first (normal -x), then left wall (normal +x)
  const Collision walls[] = {hit(response::bounce, {-1, 0}), hit(response::bounce, {1, 0})};
  EXPECT_EQ(respondVelocity(Vec2{5, 1}, walls), (Vec2{5, 1}));
  EXPECT_EQ(respondVelocity(Vec2{5, 1}, std::span<const Collision>(walls, 1)), (Vec2{-5, 1}));
}

}  // namespace
}  // namespace tv::sim
