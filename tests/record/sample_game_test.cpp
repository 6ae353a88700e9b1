// Specification of the sample platformer's recordings (app/examples): they validate, and the
// what-if re-runs show the tunnelling each mover causes or prevents — each claim beside its
// negative control.

#include <gtest/gtest.h>

#include "tv/app/platformer_game.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"

namespace {

std::vector<std::uint8_t> recordGame(bool naive) {
  tv::Recorder rec;
  (void)tv::example::play(600, naive, &rec);
  return rec.bytes();
}

tv::ReplayOptions withMover(const char* name, bool updatesAsMoves = false) {
  tv::ReplayOptions o;
  o.mover = tv::parseMover(name);
  o.updatesAsMoves = updatesAsMoves;
  return o;
}

TEST(SampleGame, ItsRecordingValidatesBitForBit) {
  tv::Replay r = tv::Replay::fromBytes(recordGame(false));
  EXPECT_TRUE(r.warnings().empty());
  const std::optional<tv::Divergence> d = r.validate();
  EXPECT_FALSE(d) << d->report();
  const std::optional<tv::Divergence> traced = r.validate({}, tv::Replay::Tracing::on);
  EXPECT_FALSE(traced) << traced->report();
  EXPECT_GT(r.summary().moves, 500u);
  EXPECT_EQ(r.label(r.items()[0].id).rfind("tile ", 0), 0u);
}

TEST(SampleGame, RecordingChangesNothingInTheGame) {
  const tv::example::Played alone = tv::example::play(600, false, nullptr);
  tv::Recorder rec;
  const tv::example::Played recorded = tv::example::play(600, false, &rec);
  EXPECT_EQ(alone.ticks, recorded.ticks);
  EXPECT_EQ(alone.stopped, recorded.stopped);
  EXPECT_EQ(alone.through, recorded.through);
}

TEST(SampleGame, TheNaiveGamesRecordingValidatesToo) {
  tv::Replay r = tv::Replay::fromBytes(recordGame(true));
  const std::optional<tv::Divergence> d = r.validate();
  EXPECT_FALSE(d) << d->report();
  const std::optional<tv::Divergence> traced = r.validate({}, tv::Replay::Tracing::on);
  EXPECT_FALSE(traced) << traced->report();
}

TEST(WhatIf, DiscreteTunnelsThroughTheThinWallWhereTheRecordedContinuousRunDidNot) {
  //   bullet 4×4 at 32 px a tick ->   |2 px wall|
  //   [#]      [#]      [#]           |         |   [#]  <- discrete lands past it
  const std::vector<std::uint8_t> file = recordGame(false);
  tv::Replay discrete = tv::Replay::fromBytes(file, withMover("discrete"));
  const tv::WhatIfReport w = discrete.whatIf();
  EXPECT_EQ(w.recordedTunnelled, 0u);  // the recorded continuous run: never
  EXPECT_GT(w.tunnelled, 20u);         // discrete: most shots at the wall
  ASSERT_TRUE(w.firstDifferentFrame);
  bool bulletThrough = false;
  for (const tv::MoveDifference& m : w.differences) {
    bulletThrough =
        bulletThrough || (m.tunnelled && discrete.label(m.item).rfind("bullet", 0) == 0);
  }
  EXPECT_TRUE(bulletThrough);
}

TEST(WhatIf, TheSameMoverReRunsTheRecordingExactly) {
  // Control for the two tests around it: with the recorded mover, what-if changes nothing.
  tv::Replay same = tv::Replay::fromBytes(recordGame(false), withMover("continuous"));
  const tv::WhatIfReport w = same.whatIf();
  EXPECT_TRUE(w.differences.empty());
  EXPECT_FALSE(w.firstDifferentFrame);
  EXPECT_EQ(w.tunnelled, 0u);
  EXPECT_GT(w.moves, 500u);
}

TEST(WhatIf, TheNaiveGameReRunWithContinuousDoesNotTunnelWhereTheRecordingDid) {
  const tv::example::Played naive = tv::example::play(600, true, nullptr);
  EXPECT_GT(naive.through, 20);  // negative control: x += v·dt passes the wall
  tv::Replay fixed = tv::Replay::fromBytes(recordGame(true), withMover("continuous", true));
  const tv::WhatIfReport w = fixed.whatIf();
  EXPECT_GT(w.recordedTunnelled, 20u);
  EXPECT_EQ(w.tunnelled, 0u);
  EXPECT_GT(w.moves, 1000u);
  ASSERT_TRUE(w.firstImplausibleFrame);  // stopped bullets are far from where the file goes on
}

TEST(WhatIf, WithoutUpdatesAsMovesTheNaiveGameHasNothingToReRun) {
  tv::Replay r = tv::Replay::fromBytes(recordGame(true), withMover("continuous"));
  const tv::WhatIfReport w = r.whatIf();
  EXPECT_EQ(w.moves, 0u);
  EXPECT_EQ(w.tunnelled, 0u);
}

// The recorded run judged alone, with no mover to re-run with: the same counts and moves as a
// what-if run's first pass, and nothing of a re-run.
TEST(CheckRecorded, FindsTheNaiveGamesOwnTunnelsAsAWhatIfsFirstPassDoes) {
  const std::vector<std::uint8_t> file = recordGame(true);
  tv::ReplayOptions updates;
  updates.updatesAsMoves = true;
  tv::Replay alone = tv::Replay::fromBytes(file, updates);
  const tv::WhatIfReport own = alone.checkRecorded();
  const tv::WhatIfReport w =
      tv::Replay::fromBytes(file, withMover("continuous", true)).whatIf();
  EXPECT_GT(own.recordedTunnelled, 20u);
  EXPECT_EQ(own.recordedTunnelled, w.recordedTunnelled);
  EXPECT_EQ(own.recordedOverlapping, w.recordedOverlapping);
  ASSERT_EQ(own.recordedFailures.size(), w.recordedFailures.size());
  for (std::size_t i = 0; i < own.recordedFailures.size(); ++i) {
    EXPECT_EQ(own.recordedFailures[i].frame, w.recordedFailures[i].frame);
    EXPECT_EQ(own.recordedFailures[i].item, w.recordedFailures[i].item);
  }
  EXPECT_EQ(own.moves, 0u);  // nothing re-run
  EXPECT_TRUE(own.differences.empty());
  // The replay is itself again afterwards: it still validates, and still has no mover.
  EXPECT_FALSE(alone.validate().has_value());
  EXPECT_THROW((void)alone.whatIf(), tv::Error);
}

TEST(CheckRecorded, TheContinuousGameHasNoTunnelOfItsOwn) {  // the control
  tv::Replay r = tv::Replay::fromBytes(recordGame(false), withMover("discrete"));
  const tv::WhatIfReport own = r.checkRecorded();
  EXPECT_EQ(own.recordedTunnelled, 0u);
  EXPECT_TRUE(own.recordedFailures.empty());
  // With a mover set, checking the recorded run leaves it set for the what-if after.
  EXPECT_GT(r.whatIf().tunnelled, 20u);
}

TEST(WhatIf, NeedsAMover) {
  tv::Replay r = tv::Replay::fromBytes(recordGame(false));
  EXPECT_THROW((void)r.whatIf(), tv::Error);
}

}  // namespace
