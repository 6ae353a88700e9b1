// The scene registry and scene parameters: every scene builds from its defaults; unknown names
// and bad values throw naming what was wrong, and change nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::sim {
namespace {

std::string errorOf(auto&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

bool mentions(const std::string& message, const std::string& what) {
  return message.find(what) != std::string::npos;
}

TEST(Registry, HoldsTheScenesTheIssueAsksFor) {
  const std::vector<std::string_view> listed = builtinScenes().names();
  const std::set<std::string_view> names(listed.begin(), listed.end());
  for (const char* n : {"bullets-wall", "rest-wall", "rest-floor", "seam-walk", "corner-graze",
                        "bounce-gap", "bullets-enemies", "platformer", "crowd", "bump-crowd"}) {
    EXPECT_TRUE(names.contains(n)) << n;
  }
  EXPECT_EQ(names.size(), builtinScenes().all().size()) << "names are unique";
}

TEST(Registry, EverySceneIsDescribedAndHasTheCommonParameters) {
  for (const SceneDef& s : builtinScenes().all()) {
    EXPECT_FALSE(s.category.empty()) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name;
    EXPECT_EQ(s.description.find('\n'), std::string::npos) << s.name << ": one line";
    const Params p = s.defaults();
    for (const std::string_view common :
         {param::speed, param::size, param::tile, param::dt, param::substep, param::offset,
          param::count, param::seed, param::cell}) {
      EXPECT_TRUE(p.has(common)) << s.name << " lacks " << common;
    }
    EXPECT_EQ(p.get(param::substep), 0.0) << s.name << ": substep defaults to tile / 2";
    const Rect cam = s.defaultCamera();
    EXPECT_TRUE(isFinite(cam) && cam.w > 0 && cam.h > 0) << s.name;
  }
}

TEST(Registry, EverySceneBuildsWithItsDefaultsForEveryMover) {
  for (const SceneDef& s : builtinScenes().all()) {
    for (const std::string_view m : moverNames()) {
      Simulation sim(s, s.defaults(), parseMover(m));
      EXPECT_GT(sim.bodies().size(), 0u) << s.name;
      EXPECT_EQ(sim.world().count(), sim.bodies().size() + sim.solids().size()) << s.name;
      EXPECT_EQ(sim.ticks(), 0u);
      for (const Body& b : sim.bodies()) {
        EXPECT_EQ(sim.world().rect(b.item), b.rect) << s.name;
      }
      sim.tick();  // and runs
      EXPECT_EQ(sim.ticks(), 1u);
    }
  }
}

TEST(Registry, TheCameraFramesTheSceneWhereverTheOffsetPutsIt) {
  // offset moves everything: the camera moves with it.
  for (const SceneDef& s : builtinScenes().all()) {
    Params p = s.defaults();
    const Rect at0 = s.camera(p);
    p.set(param::offset, 1024.0);
    const Rect moved = s.camera(p);
    EXPECT_EQ(moved.x, at0.x + 1024.0) << s.name;
    EXPECT_EQ(moved.y, at0.y + 1024.0) << s.name;
    EXPECT_EQ(moved.size(), at0.size()) << s.name;
  }
}

TEST(Registry, EverySceneRunsAFullBillionPixelsFromTheOrigin) {
  for (const SceneDef& s : builtinScenes().all()) {
    Params p = s.defaults();
    p.set(param::offset, 1e9);
    Simulation sim(s, p, parseMover("continuous"));
    for (const Body& b : sim.bodies()) EXPECT_GT(b.rect.x, 1e9 - 1e6) << s.name;
    sim.run(30);
    EXPECT_EQ(sim.counters().tunnelled, 0u) << s.name;
    EXPECT_EQ(sim.counters().overlaps, 0u) << s.name;
  }
}

TEST(Registry, AnUnknownSceneIsNamedAndTheValidOnesListed) {
  const std::string m = errorOf([] { (void)findScene("bullets-walls"); });
  EXPECT_TRUE(mentions(m, "'bullets-walls'")) << m;
  for (const std::string_view n : builtinScenes().names())
    EXPECT_TRUE(mentions(m, std::string(n))) << m;
  EXPECT_EQ(builtinScenes().tryFind("bullets-walls"), nullptr);
  EXPECT_THROW(Simulation("nope", "continuous"), Error);
  EXPECT_THROW(Simulation("bullets-wall", "nope"), Error);
}

TEST(Registry, RejectsDuplicateAndIncompleteScenes) {
  SceneRegistry r;
  SceneDef def = findScene("crowd");
  r.add(def);
  EXPECT_TRUE(mentions(errorOf([&] { r.add(def); }), "already registered"));
  SceneDef unnamed = def;
  unnamed.name.clear();
  EXPECT_THROW(r.add(unnamed), Error);
  SceneDef lacking = def;
  lacking.name = "lacking";
  lacking.params.erase(lacking.params.begin());  // no speed
  EXPECT_TRUE(mentions(errorOf([&] { r.add(lacking); }), "'speed'"));
  EXPECT_EQ(r.all().size(), 1u);
}

TEST(Params, BadValuesNameTheParameterAndTheValueAndChangeNothing) {
  Params p = findScene("bullets-wall").defaults();
  const Params before = p;
  struct Case {
    std::string_view name;
    double value;
    std::string shown;
  };
  const Case cases[] = {
      {param::speed, NAN, "nan"},   {param::speed, INFINITY, "inf"},
      {param::speed, 0.0, "0"},     {param::speed, -240.0, "-240"},
      {param::size, -1.0, "-1"},    {param::tile, 0.0, "0"},
      {param::dt, 0.0, "0"},        {param::dt, -INFINITY, "-inf"},
      {param::substep, -8.0, "-8"}, {param::offset, 1e9 + 1, "1000000001"},
      {param::count, 0.0, "0"},     {param::count, 2.5, "2.5"},
      {param::seed, -1.0, "-1"},    {param::cell, 0.0, "0"},
      {"angle", 90.0, "90"},
  };
  for (const Case& c : cases) {
    const std::string m = errorOf([&] { p.set(c.name, c.value); });
    EXPECT_TRUE(mentions(m, std::string(c.name))) << m;
    EXPECT_TRUE(mentions(m, "was " + c.shown)) << m;
  }
  for (std::size_t i = 0; i < p.values().size(); ++i) EXPECT_EQ(p.values()[i], before.values()[i]);
}

TEST(Params, AcceptTheEdgesOfTheirRanges) {
  Params p = findScene("bullets-wall").defaults();
  p.set(param::offset, 1e9);
  p.set(param::offset, -1e9);
  p.set(param::substep, 0.0);
  p.set(param::speed, 1e6);
  EXPECT_EQ(p.get(param::speed), 1e6);
}

TEST(Params, AnUnknownParameterListsTheValidOnes) {
  Params p = findScene("bounce-gap").defaults();
  const std::string m = errorOf([&] { p.set("gravity", 10); });
  EXPECT_TRUE(mentions(m, "'gravity'")) << m;
  EXPECT_TRUE(mentions(m, "gap")) << m;
  EXPECT_TRUE(mentions(m, "speed")) << m;
}

TEST(Params, ImpossibleCombinationsAreRejectedByTheScene) {
  // Crowd movers must fit a free tile: size 20 > tile 16.
  Params p = findScene("crowd").defaults();
  p.set(param::size, 20);
  const std::string m = errorOf([&] { Simulation sim(findScene("crowd"), p); });
  EXPECT_TRUE(mentions(m, "size")) << m;
  EXPECT_TRUE(mentions(m, "20")) << m;
}

TEST(Simulation, ARestartWithBadParametersLeavesEverythingAsItWas) {
  Simulation sim("crowd", "continuous");
  for (int t = 0; t < 20; ++t) sim.tick();
  const std::uint64_t hash = sim.stateHash();
  const std::uint64_t world = sim.world().stateHash();
  Params bad = findScene("crowd").defaults();
  bad.set(param::size, 20);  // valid alone, impossible for the scene
  EXPECT_THROW(sim.restart(bad), Error);
  EXPECT_THROW(sim.restart(findScene("bullets-wall").defaults()), Error);  // another scene's
  EXPECT_THROW(sim.restart(sim.params(), MoverSpec{MoverKind::substep, -1.0}), Error);
  EXPECT_EQ(sim.stateHash(), hash);
  EXPECT_EQ(sim.world().stateHash(), world);
  EXPECT_EQ(sim.ticks(), 20u);
  // A good restart starts over.
  Params fewer = sim.params();
  fewer.set(param::count, 10);
  sim.restart(fewer);
  EXPECT_EQ(sim.ticks(), 0u);
  EXPECT_EQ(sim.bodies().size(), 10u);
}

TEST(Simulation, BadConfigsAndStepsThrowNamingTheValue) {
  const SceneDef& s = findScene("rest-floor");
  EXPECT_TRUE(mentions(errorOf([&] {
                         Simulation sim(s, s.defaults(), {}, {0, 0.25});
                       }),
                       "snapshotCapacity"));
  EXPECT_TRUE(mentions(errorOf([&] { Simulation sim(s, s.defaults(), {}, {8, NAN}); }), "nan"));
  Simulation sim(s, s.defaults());
  const std::uint64_t hash = sim.stateHash();
  EXPECT_TRUE(mentions(errorOf([&] { sim.tick(-0.5); }), "-0.5"));
  EXPECT_TRUE(mentions(errorOf([&] { (void)sim.frame(NAN); }), "nan"));
  EXPECT_TRUE(mentions(errorOf([&] { sim.traceBody(99); }), "99"));
  EXPECT_TRUE(mentions(errorOf([&] { (void)sim.renderPosition(99); }), "99"));
  EXPECT_EQ(sim.stateHash(), hash);
}

TEST(Simulation, TheSubstepLengthComesFromTheSceneElseTileOverTwo) {
  const SceneDef& s = findScene("bullets-wall");
  Params p = s.defaults();
  EXPECT_EQ(Simulation(s, p, parseMover("substep-sweep")).moverSpec().maxStep, 8.0);
  p.set(param::tile, 32);
  EXPECT_EQ(Simulation(s, p, parseMover("substep-sweep")).moverSpec().maxStep, 16.0);
  p.set(param::substep, 3);
  EXPECT_EQ(Simulation(s, p, parseMover("substep-discrete")).moverSpec().maxStep, 3.0);
}

}  // namespace
}  // namespace tv::sim
