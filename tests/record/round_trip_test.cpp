// Specification of the round trip: whatever a game asks of a World while a Recorder is attached
// replays on a fresh world with the same results, bit for bit, and a tampered recording diverges
// at exactly the tampered call.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "recording_kit.hpp"
#include "tv/batch.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;
using tvtest::Script;

TEST(RoundTrip, EveryCallKindReplaysWithZeroDivergencesAndEqualState) {
  Script s;
  const std::vector<std::uint8_t> file = s.record();
  EXPECT_GT(s.nudges, 0) << "the jumper was corner-corrected";
  tv::Replay replay = tv::Replay::fromBytes(file);
  EXPECT_TRUE(replay.warnings().empty()) << replay.warnings()[0];
  const std::optional<tv::Divergence> d = replay.validate();
  ASSERT_FALSE(d) << d->report();
  EXPECT_EQ(replay.world().stateHash(), s.world.stateHash());
  EXPECT_EQ(replay.frames(), s.frames);
  // And as the debugger re-runs it: every call traced, from every keyframe.
  const std::optional<tv::Divergence> traced = replay.validate({}, tv::Replay::Tracing::on);
  ASSERT_FALSE(traced) << traced->report();
  EXPECT_EQ(replay.world().stateHash(), s.world.stateHash());

  // Every kind was exercised, so the test means what its name says.
  std::vector<bool> seen(tv::kCallKindCount, false);
  for (std::uint64_t f = 0; f < replay.frames(); ++f) {
    for (const tv::CallInfo& c : replay.calls(f)) seen[static_cast<std::size_t>(c.kind)] = true;
  }
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_TRUE(seen[k]) << "no " << tv::callKindName(static_cast<tv::CallKind>(k))
                         << " call recorded";
  }
}

// The list of recorded calls (tv/record/calls.hpp) is the file format's: a kind's code is its
// place in the list, names are unique, and the roles say which calls sweep.
TEST(CallList, CodesNamesAndRolesComeFromTheOneList) {
  std::vector<std::string_view> names;
  for (std::size_t k = 0; k < tv::kCallKindCount; ++k) {
    const auto kind = static_cast<tv::CallKind>(k);
    const std::string_view name = tv::callKindName(kind);
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 0) << name << " is listed twice";
    names.push_back(name);
    EXPECT_FALSE(tv::callWords(kind).empty()) << name;
  }
  // Codes are the file's: appending keeps them, reordering would not (FORMAT.md).
  EXPECT_EQ(static_cast<int>(tv::CallKind::add), 0);
  EXPECT_EQ(static_cast<int>(tv::CallKind::move), 3);
  EXPECT_EQ(static_cast<int>(tv::CallKind::moverMove), 11);
  EXPECT_EQ(static_cast<int>(tv::CallKind::advance), 14);
  EXPECT_EQ(tv::callKindName(static_cast<tv::CallKind>(tv::kCallKindCount)), "unknown");
  // The debugger traces the calls that are one sweep, and only those.
  std::vector<std::string_view> sweeps;
  for (std::size_t k = 0; k < tv::kCallKindCount; ++k) {
    if (tv::isOneSweep(static_cast<tv::CallKind>(k)))
      sweeps.push_back(tv::callKindName(static_cast<tv::CallKind>(k)));
  }
  EXPECT_EQ(sweeps, (std::vector<std::string_view>{"move", "check", "project", "moverMove"}));
  EXPECT_EQ(tv::callWords(tv::CallKind::batchStep), "Batch::step");
}

TEST(RoundTrip, ResultsEqualTheGameBitForBitCallByCall) {
  Script s;
  const std::vector<std::uint8_t> file = s.record();
  tv::Replay replay = tv::Replay::fromBytes(file);
  // The game's own positions after each move, against the recording's and the replay's.
  std::vector<Vec2> recorded;
  for (std::uint64_t f = 0; f < replay.frames(); ++f) {
    for (const tv::CallInfo& c : replay.calls(f)) {
      // The jumper's moves are tv::moveCornered's, not the game's own (movePositions).
      if ((c.kind == tv::CallKind::move || c.kind == tv::CallKind::moverMove) &&
          c.item != s.jumper) {
        recorded.push_back(c.position);
      }
    }
  }
  ASSERT_EQ(recorded.size(), s.movePositions.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(recorded[i].x),
              std::bit_cast<std::uint64_t>(s.movePositions[i].x))
        << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(recorded[i].y),
              std::bit_cast<std::uint64_t>(s.movePositions[i].y))
        << i;
  }
}

TEST(RoundTrip, LabelsAndCategoriesNameTheItems) {
  Script s;
  tv::Replay replay = tv::Replay::fromBytes(s.record());
  EXPECT_EQ(replay.label(s.player), "player");
  EXPECT_EQ(replay.category(s.player), "player");
  bool tile = false;
  for (const tv::RecordedItem& it : replay.items()) tile = tile || it.label == "tile 3,10";
  EXPECT_TRUE(tile);
  EXPECT_EQ(replay.label(ItemId{999, 0}), "item 999.0");
}

TEST(RoundTrip, AMidGameAttachStartsFromTheWorldAsItIs) {
  // The script removes items before attaching: free slots and generations must carry over, so
  // the re-adds after attach get the same handles on replay.
  Script s;
  const std::vector<std::uint8_t> file = s.record();
  tv::Replay replay = tv::Replay::fromBytes(file);
  replay.seek(0, 0);
  EXPECT_EQ(replay.world().state().freeSlots, s.freeAtAttach);
  EXPECT_FALSE(replay.validate());
  EXPECT_FALSE(replay.validate({}, tv::Replay::Tracing::on));
}

TEST(RoundTrip, AFileRecorderWritesTheSameBytesAsAMemoryOne) {
  const std::string path = ::testing::TempDir() + "round_trip.tvrec";
  Script a, b;
  const std::vector<std::uint8_t> memory = a.record();
  b.recordTo(path);
  const tv::Replay replay = tv::Replay::open(path);
  EXPECT_EQ(replay.fileSize(), memory.size());
  EXPECT_EQ(tvtest::readFile(path), memory);
}

TEST(RoundTrip, RecordingToAPathThatCannotBeWrittenFailsAtOnceNamingIt) {
  try {
    tv::Recorder r("/nonexistent-dir/x.tvrec");
    FAIL() << "no error";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.tvrec"), std::string::npos)
        << e.what();
  }
}

TEST(RoundTrip, AGoalEditedOnDiskDivergesAtExactlyThatCallAndTheReportNamesIt) {
  // The player walks right towards a wall, one move per frame; frame 6's goal is pushed 30 px
  // further on disk (and the chunk's checksum fixed up, as a careless tool would), into the
  // wall: the file opens, but the replayed move stops where the recorded one did not.
  //
  //   player ->        |wall|
  //   [##]  . . . . . .|    |
  //   ===================floor
  World world(16);
  world.add({0, 32, 160, 16});  // floor
  world.add({40, 0, 4, 32});    // wall
  tv::Recorder rec;
  world.attach(rec);
  const ItemId player = world.add({0, 16, 8, 16});
  rec.label(player, "player", "player");
  const double odd = 0.1234567;  // steps no float holds: goals are recorded as raw doubles
  for (int f = 0; f < 10; ++f) {
    rec.frame();
    world.move(player, world.rect(player).position() + Vec2{1.0 + odd * f, 0.0});
  }
  world.detach();
  std::vector<std::uint8_t> file = rec.bytes();
  ASSERT_FALSE(tv::Replay::fromBytes(file).validate());

  const std::vector<tv::CallInfo> calls = tv::Replay::fromBytes(file).calls(6);
  ASSERT_EQ(calls.size(), 1u);
  ASSERT_EQ(calls[0].hits, 0u);
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(calls[0].goal.x);
  ASSERT_TRUE(tvtest::replaceDouble(file, calls[0].offset, bits, calls[0].goal.x + 30.0));

  tv::Replay tampered = tv::Replay::fromBytes(file);
  const std::optional<tv::Divergence> d = tampered.validate();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->frame, 6u);
  EXPECT_EQ(d->call, 0u);
  EXPECT_EQ(d->kind, tv::CallKind::move);
  EXPECT_EQ(d->item, "player");
  EXPECT_EQ(d->what, "position");
  EXPECT_EQ(d->got, "(32, 16)");  // against the wall
  const std::string report = d->report();
  EXPECT_NE(report.find("frame 6, call 0 (move player"), std::string::npos) << report;
}

TEST(RoundTrip, LabelsGivenBeforeAttachAreKeptAndASecondAttachIsRefused) {
  World world(16);
  const ItemId a = world.add({0, 0, 8, 8});
  tv::Recorder rec;
  rec.label(a, "crate", "crate");  // before attach: written with frame 0
  world.attach(rec);
  world.move(a, {4, 0});
  world.detach();
  EXPECT_TRUE(rec.ok());
  world.attach(rec);  // the recording is closed: nothing more goes in, and it says so
  world.move(a, {8, 0});
  world.detach();
  EXPECT_FALSE(rec.ok());
  EXPECT_NE(rec.error().find("make a new Recorder"), std::string::npos) << rec.error();
  tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
  EXPECT_EQ(replay.label(a), "crate");
  EXPECT_EQ(replay.summary().moves, 1u);
  EXPECT_FALSE(replay.validate());
  EXPECT_FALSE(replay.validate({}, tv::Replay::Tracing::on));
}

TEST(RoundTrip, StepGoesCallByCallAndFillsTheTrace) {
  Script s;
  tv::Replay replay = tv::Replay::fromBytes(s.record());
  replay.seek(0, 0);
  tv::MoveTrace trace;
  std::size_t traced = 0;
  while (!replay.atEnd()) {
    trace.clear();
    const std::optional<tv::Divergence> d = replay.step(&trace);
    ASSERT_FALSE(d) << d->report();
    if (trace.item.valid() || !trace.legs.empty()) ++traced;
  }
  EXPECT_GT(traced, 10u);
}

// The debugger steps a recording with a trace, so every move takes the full path there, while
// the game recorded it untraced (the lean and narrow paths): the recorded answers (kept by pair)
// must hold every pair the traced move asks about. M drops onto the floor F and slides left into
// A; B lies beyond A, in a cell the slide's own walk reads before A's (cell 64).
//
//        B (36..46)      A (64..66, rows 0 and 1)      M (110, 20) -> goal (40, 100)
//   y 72 [====================== F =========================]
TEST(RoundTrip, AnUntracedRecordingStepsTracedWithoutAFilterDivergence) {
  World world(64);
  tv::Recorder rec;
  world.attach(rec);
  world.add({64, 40, 2, 30});  // A
  world.add({0, 72, 128, 8});  // F
  world.add({36, 66, 10, 6});  // B
  const ItemId m = world.add({110, 20, 4, 4});
  const tv::MoveResult r =
      world.move(m, {40, 100}, [](ItemId, ItemId) { return tv::response::slide; });
  ASSERT_EQ(r.collisions.size(), 2u);  // onto F, then against A
  world.detach();
  ASSERT_TRUE(rec.ok()) << rec.error();
  tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
  replay.seek(0, 0);
  tv::MoveTrace trace;
  std::size_t answers = 0;
  while (!replay.atEnd()) {
    trace.clear();
    const std::optional<tv::Divergence> d = replay.step(&trace);
    ASSERT_FALSE(d) << d->report();
    answers += trace.answers.size();
  }
  if constexpr (tv::kTraceCompiledIn) {
    EXPECT_GE(answers, 2u);  // F, then A: the move was traced
  }
}

}  // namespace

namespace {

// The game tears down its world and FixedStep before the recorder (members declared in that
// order, or a recorder kept for its report): the recorder finishes the file without touching
// them, and what it wrote replays.
TEST(RoundTrip, ARecorderOutlivingItsWorldAndFixedStepFinishesTheFile) {
  tv::Recorder rec;
  {
    World w(16);
    tv::FixedStep step;
    rec.attach(step);
    w.attach(rec);
    const ItemId m = w.add({0, 0, 8, 8});
    (void)w.add({32, 0, 16, 16});
    for (int f = 0; f < 5; ++f) {
      (void)step.advance(1.0 / 60.0);
      (void)w.move(m, w.rect(m).position() + Vec2{4, 0});
    }
  }
  rec.close();
  EXPECT_TRUE(rec.ok()) << rec.error();
  tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
  EXPECT_FALSE(replay.validate().has_value());
  EXPECT_FALSE(replay.validate({}, tv::Replay::Tracing::on).has_value());
}

}  // namespace
