// Straight to what failed: the Failures tab lists every move that failed, for every source; a
// click (and every "go") goes to that frame, traces that item, centres and zooms on it; the
// inspector and the world say in words what happened.
#include <algorithm>

#include "driver.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/still.hpp"

namespace tv::viewer {
namespace {

// The picture tv-render (and the debugger's --screenshot) draws for these flags, as both parse
// them.
std::unique_ptr<ui::Still> still(const std::vector<std::string>& given) {
  std::vector<std::string> args = {"tv-render"};
  args.insert(args.end(), given.begin(), given.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::vector<char*> rest;
  const auto r = ui::extractRecordingFlags(static_cast<int>(argv.size()), argv.data(), false, rest);
  const ui::PictureOptions o = ui::parsePictureOptions(static_cast<int>(rest.size()), rest.data());
  return std::make_unique<ui::Still>(o, r);
}

// Draws the still's picture as tv-render does (a few frames: panels settle), for drawnText.
void draw(ui::Still& s) {
  s.beginImage();
  for (int f = 0; f < 4; ++f) {
    ImGui::NewFrame();
    s.drawFrame(ImGui::GetIO().DisplaySize);
    ImGui::Render();
  }
}

// bullets-wall at 1920 px/s with the naive mover: most of the 1000 bullets pass the wall, each
// in its own lane, in the tick it reaches it.
//
//    lane k   [b]--32px-->  |####|  [b]
TEST_F(DebuggerDriver, TheFailuresTabListsEveryTunnelledBulletByName) {
  open({"--scene", "bullets-wall", "--mover", "discrete", "--tick", "1"});
  const ui::FailureList& list = dbg().checks().failures();
  ASSERT_TRUE(list.complete);
  // One row per tunnel the scene counts, each naming its body and the wall tile it passed.
  std::uint64_t rows = 0;
  for (const auto& e : list.entries) {
    if (e.failure.kind != ui::FailureKind::tunnelled) continue;
    ++rows;
    EXPECT_TRUE(e.failure.item.valid());
    EXPECT_EQ(e.failure.what.rfind("tunnelled through wall tile", 0), 0u) << e.failure.what;
  }
  // As many as the scene counts over the whole run.
  const sim::SceneDef& scene = sim::findScene("bullets-wall");
  sim::Simulation whole(scene, scene.defaults(), MoverSpec{.kind = MoverKind::discrete});
  (void)whole.run(1000);
  EXPECT_EQ(rows, whole.counters().tunnelled);
  EXPECT_GT(rows, 500u);
}

TEST_F(DebuggerDriver, AnExactMoverListsNoFailure) {  // the negative control
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "1"});
  ASSERT_TRUE(dbg().checks().failures().complete);
  EXPECT_TRUE(dbg().checks().failures().entries.empty());
}

// A click goes to that frame, traces that item, centres and zooms on it, and the inspector
// shows the failing panel's move, in words.
TEST_F(DebuggerDriver, AClickOnAFailureGoesThereTracesCentresAndZooms) {
  open({"--scene", "bullets-wall", "--compare", "continuous,discrete", "--tick", "1", "--body",
        "0", "--view", "scene"});
  const auto& entries = dbg().checks().failures().entries;
  ASSERT_FALSE(entries.empty());
  // The last listed: a late one, in the discrete panel (panel 1).
  const std::size_t pick = entries.size() - 1;
  const ui::FailureList::Entry e = entries[pick];
  EXPECT_EQ(e.panel, 1u);
  const double homeScale = dbg().panels()[0].camera.scale();
  dbg().goToFailure(pick);
  frames(3);
  EXPECT_EQ(dbg().currentTick(), e.failure.frame);
  EXPECT_EQ(dbg().session().traced(), e.failure.item);
  EXPECT_EQ(dbg().view().inspected, 1u);
  EXPECT_TRUE(dbg().following());
  // Centred on the traced item, and zoomed in from the scene's whole view.
  const Rect item = dbg().session().panel(1).world().rect(e.failure.item);
  const Rect view = dbg().panels()[1].camera.view();
  EXPECT_TRUE(contains(view, item.center()));
  EXPECT_GT(dbg().panels()[1].camera.scale(), homeScale * 4.0);
  // The inspector says what happened, in the discrete panel's words.
  const std::string details = drawnText("Details");
  EXPECT_NE(details.find("tunnelled through wall tile"), std::string::npos) << details;
}

// "first failure: tick 1 ... go" used to go to tick 1 with body 2 still traced, and body 2 only
// tunnels at tick 2: all three panels looked the same. Now "go" shows a body that failed there.
TEST_F(DebuggerDriver, GoOnTheFirstFailureShowsABodyThatFailedThere) {
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous", "--tick",
        "2", "--body", "2", "--view", "follow"});
  ASSERT_TRUE(dbg().checks().firstFailure().has_value());
  const std::uint64_t first = *dbg().checks().firstFailure();
  dbg().command(Command::firstFailure);
  frames(2);
  EXPECT_EQ(dbg().currentTick(), first);
  const auto traced = dbg().session().traced();
  ASSERT_TRUE(traced.has_value());
  // The traced body's move in that tick is one the scene counted as a failure.
  const ui::Source& failing = dbg().session().panel(dbg().view().inspected);
  ASSERT_FALSE(failing.history().empty());
  EXPECT_EQ(failing.history().back().tick, first);
  EXPECT_TRUE(failing.failureOf(failing.history().back()).has_value());
  // The world says it too.
  const std::string world = drawnText("###panel");
  EXPECT_NE(world.find("tunnelled through"), std::string::npos) << world;
}

// A recording's what-if: the Failures tab lists each re-run bullet that tunnelled; "go" beside
// "runs differ" traces the item whose move ended elsewhere first (it kept the player traced).
TEST_F(DebuggerDriver, ARecordingsWhatIfListsItsTunnelsAndGoTracesWhatDiffers) {
  open({sampleRecording(), "--frame", "60", "--what-if", "discrete"});
  const auto& entries = dbg().checks().failures().entries;
  ASSERT_FALSE(entries.empty());
  EXPECT_TRUE(std::all_of(entries.begin(), entries.end(),
                          [](const auto& e) { return e.panel == 1; }))
      << "the recorded run validates: its failures are none";
  const std::string player = "player";
  dbg().show(60, std::nullopt, player);
  ASSERT_TRUE(dbg().checks().whatIf().has_value());
  const MoveDifference first = dbg().checks().whatIf()->differences.front();
  dbg().goToDifference();
  frames(2);
  EXPECT_EQ(dbg().currentTick(), first.frame);
  EXPECT_EQ(dbg().session().traced(), first.item);
  EXPECT_NE(dbg().session().primary().describe(first.item), player);
  // And a click on a listed tunnel shows that bullet's re-run move, the call selected.
  dbg().goToFailure(0);
  frames(2);
  EXPECT_EQ(dbg().currentTick(), entries[0].failure.frame);
  EXPECT_EQ(dbg().session().call(), entries[0].failure.call);
  EXPECT_EQ(dbg().session().traced(), entries[0].failure.item);
  EXPECT_NE(dbg().session().panel(1).callTrace(), nullptr);
}

// A game whose own mover tunnels: its recording lists the recorded run's failures itself, with
// no what-if asked for. The bullet moves 32 px a frame with the naive mover, so from frame 1
// to frame 2 it is on either side of the 4 px wall and never touched it.
//
//    frame 1   [b]        |#|          frame 2         |#|   [b]
//              x 32       x 40..44                     x 64
TEST_F(DebuggerDriver, ARecordingListsTheGamesOwnTunnelsWithoutAWhatIf) {
  const std::string path = ::testing::TempDir() + "tv_own_tunnel.tvrec";
  {
    World w(16);
    Recorder rec(path);
    w.attach(rec);
    const ItemId wall = w.add({40, 0, 4, 32});
    rec.label(wall, "wall", "wall");
    const ItemId bullet = w.add({0, 10, 2, 2});
    rec.label(bullet, "bullet 1", "bullet");
    Mover naive(parseMover("discrete"));
    for (int f = 0; f < 4; ++f) {
      (void)naive.move(w, bullet, w.rect(bullet).position() + Vec2{32, 0});
      rec.frame();
    }
    w.detach();
  }
  open({path});
  const auto& entries = dbg().checks().failures().entries;
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].panel, 0u);
  EXPECT_EQ(entries[0].failure.frame, 1u);
  EXPECT_EQ(entries[0].failure.kind, ui::FailureKind::tunnelled);
  EXPECT_EQ(entries[0].failure.what, "tunnelled through wall");
  EXPECT_EQ(dbg().session().primary().describe(entries[0].failure.item), "bullet 1");
  // The tab says so, and a click goes there with the bullet traced.
  dbg().command(Command::failures);
  frames(2);
  EXPECT_NE(drawnText().find("tunnelled through wall"), std::string::npos) << drawnText();
  dbg().goToFailure(0);
  frames(2);
  EXPECT_EQ(dbg().currentTick(), 1u);
  EXPECT_EQ(dbg().session().traced(), entries[0].failure.item);
}

// A game that moves its bullet by updates (x += v*dt, update), opened with a what-if that makes
// updates moves, as tv-replay --what-if continuous --updates-as-moves reads it: the recorded
// run's tunnel is listed and the bullet is drawn as a body. The debugger said "no failure" (it
// judged the recorded run's moves only: there are none) and drew the bullet as scenery.
//
//     bullet ■ --32--> |wall|  (4 px thick, at x 40: the second update lands past it)
TEST_F(DebuggerDriver, AGameThatMovesByUpdatesHasItsTunnelsListedUnderUpdatesAsMoves) {
  const std::string path = ::testing::TempDir() + "tv_update_tunnel.tvrec";
  ItemId bullet;
  {
    World w(16);
    Recorder rec(path);
    w.attach(rec);
    const ItemId wall = w.add({40, 0, 4, 32});
    rec.label(wall, "wall", "wall");
    bullet = w.add({0, 10, 2, 2});
    rec.label(bullet, "bullet 1", "bullet");
    for (int f = 0; f < 4; ++f) {
      w.update(bullet, w.rect(bullet).position() + Vec2{32, 0});
      rec.frame();
    }
    w.detach();
  }
  open({path});  // the control: without the what-if, updates are not moves
  EXPECT_TRUE(dbg().checks().failures().entries.empty());
  open({path, "--what-if", "continuous", "--updates-as-moves"});
  const auto& entries = dbg().checks().failures().entries;
  const auto recorded = std::find_if(entries.begin(), entries.end(),
                                     [](const auto& e) { return e.panel == 0; });
  ASSERT_NE(recorded, entries.end()) << "the recorded run's tunnel is not listed";
  EXPECT_EQ(recorded->failure.kind, ui::FailureKind::tunnelled);
  EXPECT_EQ(recorded->failure.frame, 1u);
  // Drawn as a body, not as the level's geometry.
  ASSERT_NE(dbg().session().primary().replay(), nullptr);
  EXPECT_TRUE(dbg().session().primary().replay()->moves(bullet));
}

// A failure's words wrap in the column; the row is as tall as they are, so the next row's
// "frame 62 call 2" is not written over the last word of "... 32 from the recorded end".
TEST_F(DebuggerDriver, AFailureRowIsAsTallAsItsWrappedWords) {
  for (const float w : {1280.0f, 1024.0f}) {
    resize(w, w == 1280.0f ? 720.0f : 640.0f);
    open({sampleRecording(), "--what-if", "discrete", "--tab", "failures"});
    frames(3);
    ASSERT_GT(dbg().checks().failures().entries.size(), 3u);
    const std::string rows = drawnText("failure rows");
    EXPECT_NE(rows.find("tunnelled through wall"), std::string::npos) << rows;
    std::string where;
    EXPECT_EQ(overlappingGlyphs("failure rows", &where), 0) << w << ": " << where;
  }
}

// The inspector and the world say what happened to the traced move.
TEST_F(DebuggerDriver, TheInspectorAndTheWorldSayWhatHappened) {
  open({"--scene", "bullets-wall", "--mover", "discrete", "--tick", "2", "--body", "2", "--view",
        "follow"});
  frames(2);
  const std::string inspector = drawnText("Details");
  EXPECT_NE(inspector.find("tunnelled through wall tile"), std::string::npos) << inspector;
  const std::string world = drawnText("World");
  EXPECT_NE(world.find("tunnelled through wall tile"), std::string::npos) << world;
  // The exact sweep: stopped against the wall, in green words.
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "2", "--body", "2", "--view",
        "follow"});
  frames(2);
  const std::string stopped = drawnText("World");
  EXPECT_NE(stopped.find("stopped against wall tile"), std::string::npos) << stopped;
  EXPECT_EQ(stopped.find("tunnelled"), std::string::npos) << stopped;
}

// tv-render --first-failure draws the moment "go" shows in the debugger: the same tick, the same
// failing body traced (a bullet that tunnels there, not the body the flags would trace), the
// inspector and the world saying what happened, the row marked in the Failures tab.
TEST_F(DebuggerDriver, AStillAtTheFirstFailureIsWhereGoGoes) {
  open({"--scene", "bullets-wall", "--mover", "discrete", "--first-failure"});
  const auto shot = still({"--scene", "bullets-wall", "--mover", "discrete", "--first-failure"});
  ASSERT_TRUE(shot->failureShown().has_value());
  EXPECT_EQ(shot->session().frame(), dbg().currentTick());
  EXPECT_EQ(shot->session().traced(), dbg().session().traced());
  EXPECT_EQ(shot->failures().entries.size(), dbg().checks().failures().entries.size());
  const ui::Failure& f = shot->failures().entries[*shot->failureShown()].failure;
  EXPECT_EQ(f.kind, ui::FailureKind::tunnelled);
  EXPECT_EQ(shot->session().traced(), f.item);
  shot->advanceTo(1);  // tv-render's tick loop: the failure's tick stays
  EXPECT_EQ(shot->session().frame(), f.frame);
  draw(*shot);
  EXPECT_NE(drawnText("Details").find("tunnelled through wall tile"), std::string::npos);
  EXPECT_NE(drawnText("World").find("tunnelled through wall tile"), std::string::npos);
}

TEST_F(DebuggerDriver, AStillOfARunThatNeverFailsSaysSoInsteadOfAPicture) {  // negative control
  try {
    (void)still({"--scene", "bullets-wall", "--mover", "continuous", "--first-failure"});
    FAIL() << "the exact sweep never tunnels: there is no failure to show";
  } catch (const ui::NoFailure& e) {
    EXPECT_NE(e.message.find("no move of bullets-wall"), std::string::npos) << e.message;
  }
}

// tv-render --open FILE --what-if discrete --first-failure: the recorded run beside its re-run
// at the first re-run move that tunnelled — the call the what-if report names, its bullet
// traced in both panels, the re-run's move saying it went through the wall.
TEST_F(DebuggerDriver, AWhatIfStillOpensAtTheFirstReRunMoveThatTunnelled) {
  const auto shot = still({"--open", sampleRecording(), "--what-if", "discrete", "--first-failure"});
  ReplayOptions ro;
  ro.mover = MoverSpec{.kind = MoverKind::discrete};
  ro.tolerant = true;
  const WhatIfReport report = Replay::open(sampleRecording(), ro).whatIf();
  const auto first = std::find_if(report.differences.begin(), report.differences.end(),
                                  [](const MoveDifference& d) { return d.tunnelled || d.overlapping; });
  ASSERT_NE(first, report.differences.end());
  ASSERT_EQ(shot->session().size(), 2u);
  EXPECT_EQ(shot->session().frame(), first->frame);
  EXPECT_EQ(shot->session().call(), first->call);
  EXPECT_EQ(shot->session().traced(), first->item);
  ASSERT_NE(shot->session().panel(1).callTrace(), nullptr);
  // Every re-run tunnel is listed, against the what-if panel.
  EXPECT_EQ(shot->failures().entries.size(), report.tunnelled + report.overlapping);
  draw(*shot);
  EXPECT_NE(drawnText("Details").find("tunnelled through wall"), std::string::npos)
      << drawnText("Details");
  // The first re-run move that differs is not always a failure: this one is (a control that the
  // still did not merely go to the first difference).
  EXPECT_TRUE(first->tunnelled);
}

TEST_F(DebuggerDriver, AWhatIfUnderAnExactMoverHasNoFailureToShow) {  // negative control
  EXPECT_THROW(
      (void)still({"--open", sampleRecording(), "--what-if", "continuous", "--first-failure"}),
      ui::NoFailure);
}

}  // namespace
}  // namespace tv::viewer
