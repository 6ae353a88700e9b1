#pragma once
/// Runs one scene with one mover at a fixed step, keeps a ring of per-tick snapshots to step
/// back through, and hashes its state so determinism is a number a test can compare.
///
/// A tick, for each active body in body order (unless the scene is batched):
///   1. the scene's rules steer (set velocities) — once per tick, before anything moves;
///      then the bodies that are moving solids (Body::solid) move, by tv::moveSolid, carrying
///      and pushing the others (which the mover then moves as below);
///   2. gravity: v += g·dt for bodies that fall;
///   3. the mover moves the body towards position + v·dt, its filter choosing the body's
///      response for every solid and every body its mask meets (others are ignored);
///   4. each collision updates the velocity (`respondVelocity`: touch stops, slide zeroes the
///      normal component, bounce reflects it);
///   5. the rules look at the move and count.
/// A batched scene moves all active bodies through one tv::Batch instead (the mover is unused).
/// Nothing reads a clock: a simulation's state depends only on its scene, parameters, mover and
/// the number of ticks (and their dt, if `tick(dt)` is used).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tv/batch.hpp"
#include "tv/contact.hpp"
#include "tv/mover.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/timestep.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv::sim {

/// How much history a Simulation keeps, and its frame clamp.
struct SimConfig {
  /// Ticks kept for `stepBack` and `seek`, counting the current one; >= 1. Default 600
  /// (10 s at 60 Hz). Memory: about 40 bytes per body per tick, and some 300 more per body that
  /// reads its contacts (Body::contacts: its tv::Contacts state is kept too).
  std::size_t snapshotCapacity = 600;
  /// Longest frame `frame()` counts, s (the spiral-of-death guard); raised to dt when dt is
  /// longer. Finite and > 0. Default 0.25.
  double maxFrameTime = 0.25;
};

/// What tracing saw (not part of the state: tracing never changes results).
struct TraceStats {
  std::uint64_t moves = 0;       ///< traced moves
  std::uint64_t candidates = 0;  ///< narrow-phase candidates over those moves
  std::uint64_t cells = 0;       ///< broad-phase cells over those moves
};

/// One scene run by one mover: tick it, step back, seek, hash it, trace a body.
///
///     tv::sim::Simulation sim("bullets-wall", "discrete");
///     sim.run(600);
///     std::printf("%llu tunnelled\n", (unsigned long long)sim.counters().tunnelled);
class Simulation {
 public:
  /// Builds `scene` with `params` (which must be the scene's own, e.g. from
  /// `scene.defaults()`), moved by `mover`. The substep movers' piece length is the scene's
  /// `substep` parameter, or else the spec's `maxStep`, or else tile / 2. Throws tv::Error on
  /// bad parameters, a bad mover spec or a bad config.
  Simulation(const SceneDef& scene, const Params& params, MoverSpec mover = {},
             SimConfig config = {});
  /// A built-in scene at its defaults, with a mover by name (see tv::moverNames()).
  Simulation(std::string_view scene, std::string_view mover);

  /// Rebuilds the scene from tick 0 with new parameters / another mover. On a throw (bad value,
  /// parameters of another scene) nothing changes: the world, bodies and ring stay as they were.
  void restart(const Params& params);
  /// As `restart(params)`, with another mover too.
  void restart(const Params& params, MoverSpec mover);
  /// From tick 0 with the same parameters and mover.
  void restart();

  // -- stepping ------------------------------------------------------------------------------
  /// One tick of the scene's dt.
  void tick();
  /// One tick of `dt` seconds (finite, > 0): a variable-step game loop, for experiments with
  /// jittered steps. Snapshots and hashes work as for `tick()`.
  void tick(double dt);
  /// Adds one rendered frame (seconds, finite and >= 0) to the fixed-step accumulator and runs
  /// the ticks it calls for; returns how many. Throws tv::Error on a bad frame time.
  int frame(double frameTime);
  /// Ticks until the scene is finished or `maxTicks` more have run; returns how many ran.
  std::uint64_t run(std::uint64_t maxTicks);
  /// The scene's rules say nothing more can happen.
  [[nodiscard]] bool finished() const;

  // -- rendering -----------------------------------------------------------------------------
  /// Where the last frame falls between the previous tick (0) and the current one (1).
  [[nodiscard]] double alpha() const { return fixed_.alpha(); }
  /// Body `i` between its previous and current positions at `alpha()` (after a seek, the
  /// restored position).
  [[nodiscard]] Vec2 renderPosition(std::size_t i) const;
  /// Body `i`'s rect at its render position.
  [[nodiscard]] Rect renderRect(std::size_t i) const;
  /// The accumulator `frame()` runs ticks from.
  [[nodiscard]] const FixedStep& fixedStep() const { return fixed_; }

  // -- time travel ---------------------------------------------------------------------------
  /// Restores the previous tick's snapshot. Throws tv::Error when it is not in the ring.
  void stepBack();
  /// Restores tick `t` exactly (bodies, world, counters, the mover's own state). A tick in the
  /// ring is restored directly; a later one is reached by ticking forward from the newest
  /// snapshot at the scene's dt. Throws tv::Error naming the tick and the ring's range if `t`
  /// has already left the ring.
  void seek(std::uint64_t t);
  /// True when the previous tick's snapshot is in the ring.
  [[nodiscard]] bool canStepBack() const { return tick_ > oldest_; }
  /// The range of ticks the ring holds (newest may be ahead of the current tick after a step
  /// back; the next tick discards the snapshots ahead).
  [[nodiscard]] std::uint64_t oldestTick() const { return oldest_; }
  [[nodiscard]] std::uint64_t newestTick() const { return newest_; }  ///< see oldestTick()

  // -- state ---------------------------------------------------------------------------------
  /// Ticks run since tick 0 (the current tick's number).
  [[nodiscard]] std::uint64_t ticks() const { return tick_; }
  /// Hash of the tick number, every body's position, velocity, state and activity (as bits),
  /// and every counter. Deterministic across runs, instances and render rates.
  [[nodiscard]] std::uint64_t stateHash() const;
  [[nodiscard]] const Counters& counters() const { return counters_; }  ///< what was counted
  [[nodiscard]] std::span<const Body> bodies() const { return bodies_; }  ///< scene order
  [[nodiscard]] std::span<const Solid> solids() const { return solids_; }  ///< scene order
  [[nodiscard]] const World& world() const { return world_; }  ///< the world the bodies move in
  /// Reports every call the simulation makes on its world to `observer` from now on (a
  /// tv::Recorder records the scene; see World::attach), until `detach`.
  void attach(WorldObserver& observer) { world_.attach(observer); }
  /// Stops reporting to the observer given to `attach`.
  void detach() { world_.detach(); }
  [[nodiscard]] const SceneDef& scene() const { return scene_; }  ///< the scene it runs
  [[nodiscard]] const Params& params() const { return params_; }  ///< its parameters
  /// The mover's spec as used (maxStep resolved).
  [[nodiscard]] const MoverSpec& moverSpec() const { return mover_.spec(); }
  [[nodiscard]] Vec2 gravity() const { return gravity_; }  ///< px/s²
  /// The scene's fixed step, s.
  [[nodiscard]] double dt() const { return dt_; }
  /// What the tools frame, at the current parameters.
  [[nodiscard]] Rect camera() const { return scene_.camera(params_); }
  /// What the tools call solid `i` and body `i`: the scene's own name for it (a map object's),
  /// else empty.
  [[nodiscard]] std::string_view solidName(std::size_t i) const {
    return i < solidNames_.size() ? std::string_view(solidNames_[i]) : std::string_view();
  }
  /// What the tools call body `i`, as solidName.
  [[nodiscard]] std::string_view bodyName(std::size_t i) const {
    return i < bodyNames_.size() ? std::string_view(bodyNames_[i]) : std::string_view();
  }
  /// The solid whose item this is (solids are added first, in order), if it is one.
  [[nodiscard]] std::optional<std::size_t> solidOf(ItemId id) const;

  // -- tracing -------------------------------------------------------------------------------
  /// Records a MoveTrace of body `i`'s move every tick (nullopt: off, the default). Tracing
  /// never changes results; batched scenes record nothing (tv::Batch has no trace).
  void traceBody(std::optional<std::size_t> i);
  [[nodiscard]] std::optional<std::size_t> tracedBody() const { return traced_; }  ///< or none
  /// The traced body's move in the last tick, or null (off, inactive, batched, after a seek).
  [[nodiscard]] const MoveTrace* lastTrace() const { return traceValid_ ? &trace_ : nullptr; }
  /// Totals over every traced move since the last restart.
  [[nodiscard]] const TraceStats& traceStats() const { return traceStats_; }

  // -- what was counted ----------------------------------------------------------------------
  /// What the rules counted in the last tick, body by body, in the order it happened (empty
  /// after a seek, a step back or a restart). Not part of the state; costs a few compares a move.
  [[nodiscard]] std::span<const TickEvent> events() const { return events_; }
  /// What the moving solids (Body::solid) did in the last tick — each body they carried,
  /// pushed or squished, solid by solid in body order, each solid's in the order tv::moveSolid
  /// reports them (squishes, then pushes, then carries). Kept with each snapshot: a step back or
  /// a seek shows that tick's. Not part of the state.
  [[nodiscard]] std::span<const SolidContact> solidContacts() const { return contacts_; }
  /// The corner corrections (Body::maxNudge) made in the last tick, in body order; kept with
  /// each snapshot as solidContacts. Not part of the state.
  [[nodiscard]] std::span<const CornerNudgeAt> cornerNudges() const { return nudges_; }
  /// The contact events of the last tick of the bodies that read their contacts
  /// (Body::contacts), body by body in body order, each body's in tv::Contacts' order; kept with
  /// each snapshot as solidContacts. Not part of the state.
  [[nodiscard]] std::span<const ContactAt> contactEvents() const { return contactEvents_; }
  /// What body `i` stands on after its last update (tv::Contacts::ground); nullopt for a body
  /// that does not read its contacts. Restored with each snapshot. Throws tv::Error for a body
  /// that does not exist.
  [[nodiscard]] std::optional<Ground> ground(std::size_t i) const;
  /// Moves reporting more collisions than `n` are listed in events() (0, the default: none).
  void setManyCollisions(std::size_t n) { manyCollisions_ = n; }
  /// The threshold setManyCollisions set (0: off).
  [[nodiscard]] std::size_t manyCollisions() const { return manyCollisions_; }

 private:
  struct BodyState {
    Vec2 position;
    Vec2 velocity;
    std::int32_t state = 0;
    bool active = true;
  };
  struct Snapshot {
    std::vector<BodyState> bodies;
    Counters counters;
    TraceStats traceStats;  // so stepping back through history does not count moves twice
    std::vector<SolidContact> contacts;
    std::vector<CornerNudgeAt> nudges;
    std::vector<ContactAt> contactEvents;
    Contacts tracker;  // only in scenes whose bodies read their contacts
    bool hasMover = false;
    Mover mover;  // only movers with per-item state (pixel); others keep none between moves
  };

  void build(SceneSetup setup);
  void step(double dt);
  void stepOrThrow(double dt);
  void moveOneByOne(TickContext& ctx, double dt);
  void moveBatched(TickContext& ctx, double dt);
  void moveSolids(double dt);  // the bodies that are moving solids, by tv::moveSolid
  MoveResult moveCornered(std::size_t body, Vec2 goal, const Filter& filter);
  void readContacts(std::size_t body, const Filter& filter, std::span<const Collision> met);
  void record();
  void restore(std::uint64_t t);
  void syncWorld(std::size_t i);
  void noteTrace();
  void noteCounted(const Counters& before, std::int64_t body, const Rect& start,
                   std::size_t collisions, std::size_t mark);
  [[nodiscard]] ResponseId respond(ItemId item, ItemId other) const;
  [[nodiscard]] TickContext context(double dt);

  SceneDef scene_;
  Params params_;
  SimConfig config_;
  MoverSpec requested_;  // as given (maxStep unresolved), for restarts with new parameters
  double dt_ = 1.0 / 60.0;
  World world_;
  Mover mover_;
  Batch batch_;
  FixedStep fixed_;

  std::vector<Solid> solids_;
  std::vector<Body> bodies_;
  std::vector<std::string> solidNames_, bodyNames_;
  std::vector<ItemId> solidItems_;
  Vec2 gravity_;
  std::shared_ptr<const SceneRules> rules_;
  std::vector<std::int32_t> bodyBySlot_;
  std::vector<std::uint8_t> tagBySlot_;
  std::vector<std::uint8_t> oneWayBySlot_;  // world slot -> 1 for a one-way solid

  Counters counters_;
  std::uint64_t tick_ = 0;
  std::vector<Vec2> previous_;
  std::vector<Vec2> previousBefore_;  // previous_ as it was before the tick now running

  std::vector<Snapshot> ring_;
  std::uint64_t oldest_ = 0, newest_ = 0;

  std::optional<std::size_t> traced_;
  MoveTrace trace_;
  bool traceValid_ = false;
  TraceStats traceStats_;

  std::vector<TickEvent> events_;
  std::vector<SolidContact> contacts_;
  std::vector<CornerNudgeAt> nudges_;
  // Contacts of the bodies that read them (Body::contacts): the game's tracker, and the items it
  // lists as one-way platforms and as moving solids.
  bool readsContacts_ = false;
  Contacts tracker_;
  std::vector<ContactAt> contactEvents_;
  std::vector<ItemId> contactOneWay_, contactSolids_;
  std::vector<Collision> cornered_;  // the last corner-corrected move's collisions
  std::size_t manyCollisions_ = 0;
  std::vector<BatchMove> batchMoves_;
  std::vector<ItemId> riders_;  // every body that is not a moving solid
  std::vector<std::size_t> batchBodies_;
};

}  // namespace tv::sim
