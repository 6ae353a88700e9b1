#pragma once
// The world userdata shared by `tunnelvision` and `tunnelvision.bump`: a tv::World plus what a
// Lua binding needs around it — the item <-> handle maps (in Lua tables, so that item identity
// is exactly Lua's raw table-key equality), the responses by name, bump.lua's cell count.

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <lua.hpp>

#include "tv/batch.hpp"
#include "tv/contact.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/world.hpp"

namespace tvlua {

// Slots of a world's environment table (lua_setfenv on the userdata).
enum Env : int {
  kItemToSlot = 1,   // item -> slot index (number)
  kSlotToItem = 2,   // slot index + 1 -> item
  kNameToId = 3,     // response name -> core ResponseId
  kSentinel = 4,     // weak-valued: [1] a table that dies at the next collection (countCells)
  kIdToFn = 5,       // core ResponseId -> the Lua function of a response added from Lua
  kIdToName = 6,     // core ResponseId -> the name Lua knows it by
  kSavedCols = 7,    // during a move: collision tables a Lua response saw, by collision index
  kKeys = 8,         // the collision tables' field names, interned once (see Key)
  kInternals = 9,    // bump's internal tables as last read (internals.cpp): rows, rects...
  kFilter = 10,      // during a move with bump's rules: its filter (false: none), for kVisited
  kVisited = 11,     // bump's `visitedFilter`, handed to responses added from Lua
  kSerials = 12,     // label base -> how many items got it (labels.cpp)
  kBumpResponses = 13,  // the module's bump.responses table (world.responses' built-ins)
  kEnvSize = 13
};

// Field names of a collision table, by index in env[kKeys]: setting fields with keys already
// on hand skips hashing each name again, most of the cost of building bump's tables.
enum Key : int {
  kKeyItem = 1, kKeyOther, kKeyType, kKeyOverlaps, kKeyTi, kKeyMove, kKeyNormal, kKeyTouch,
  kKeyItemRect, kKeyOtherRect, kKeySlide, kKeyBounce, kKeyX, kKeyY, kKeyW, kKeyH, kKeyCount
};
/// Pushes the table of field names (for newWorld's second upvalue).
void pushKeys(lua_State* L);

/// bump.lua's grid, kept only to count cells as bump does (countCells): cell (cx, cy), 1-based,
/// from floor(x / size) + 1 to ceil((x + w) / size), and an emptied cell lives on until the
/// next garbage collection (bump's cells sit in weak tables).
class BumpCells {
 public:
  struct Range {
    std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    friend bool operator==(const Range&, const Range&) = default;
  };
  explicit BumpCells(double size) : size_(size) {}
  [[nodiscard]] Range of(const tv::Rect& r) const;
  /// Registers (+1) or unregisters (-1) an item over a range; returns true when a cell emptied.
  bool add(const Range& r);
  bool remove(const Range& r);
  [[nodiscard]] std::size_t occupied() const { return counts_.size(); }
  [[nodiscard]] std::size_t pending() const { return emptied_.size(); }
  void collect() { emptied_.clear(); }

 private:
  struct Hash {
    std::size_t operator()(std::uint64_t k) const noexcept { return k * 0x9E3779B97F4A7C15ull; }
  };
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y);
  }
  double size_;
  std::unordered_map<std::uint64_t, std::uint32_t, Hash> counts_;
  std::unordered_set<std::uint64_t, Hash> emptied_;
};

struct CallContext;

/// A collision as the fast path hands it to Lua through the FFI (fast_path.lua declares the
/// same struct): plain numbers, read by field.
struct FastCollision {
  double ti, moveX, moveY, normalX, normalY, touchX, touchY;
  double itemX, itemY, itemW, itemH, otherX, otherY, otherW, otherH;
  double targetX, targetY;
  std::int32_t other;     // the other item's slot
  std::int32_t response;  // its response id (the name is env[kIdToName][response])
  std::int32_t overlaps;  // 0 or 1
  std::int32_t unused;
};

struct LuaWorld {
  static constexpr std::uint64_t kMagic = 0x74766C7561776F72ull;
  explicit LuaWorld(double cellSize) : world(cellSize), cells(cellSize) {}
  ~LuaWorld();
  LuaWorld(const LuaWorld&) = delete;
  LuaWorld& operator=(const LuaWorld&) = delete;

  std::uint64_t magic = kMagic;
  tv::World world;
  /// The Lua call on this world that is running (its filter, item, stack slots), innermost
  /// first through `outer`: what a response added from Lua reads (CallScope sets it).
  CallContext* current = nullptr;
  /// bump.lua's rules for move, check, project and the queries (`tunnelvision.bump` worlds);
  /// false: the core's (`tunnelvision` worlds, or after setMover).
  bool bumpRules = true;
  /// Counts changes to items, so that bump's internal tables are rebuilt only when read after
  /// one (internals.cpp).
  std::uint64_t version = 0;
  std::unique_ptr<tv::Mover> mover;  // null: World::move, the exact continuous move
  tv::Batch batch;
  BumpCells cells;
  std::vector<BumpCells::Range> ranges;  // per slot: the bump cells its item is registered in
  std::vector<tv::Collision> last;   // the last `go`'s collisions (getCollision)
  std::vector<FastCollision> fastCols;  // the last fast-path move's (fast_path.cpp)
  std::vector<tv::BatchMove> moves;  // the batch step's input
  // world:contacts (platforms.cpp): the tracker kept between updates, and its inputs' storage
  // (members, so that an argument error raised while filling them leaks nothing).
  tv::Contacts contacts;
  std::vector<tv::ItemId> oneWayItems, solidItems;
  std::vector<tv::Collision> metCols;
  // Query and project scratch, one per nesting level (a filter may query the same world).
  struct Scratch {
    std::vector<tv::ItemId> items;
    std::vector<tv::Collision> cols;
  };
  std::vector<std::unique_ptr<Scratch>> scratch;
  std::size_t scratchDepth = 0;
  std::vector<tv::Rect> starts;      // the batch step's bodies, before it
  bool luaResponses = false;         // a response was added from Lua
  int recordNumber = 0;              // automatic recording: which file this world writes (1...)
  bool framesByLove = false;         // ... whose frames love.run's steps mark (world:frame waits)
  bool streaming = false;            // ... streaming live to the TV_LIVE receiver
  tv::ResponseId slide = tv::response::slide;  // what 'slide' names: the answer without a filter
  int busy = 0;  // > 0 while one of this world's filters or responses runs
  std::unique_ptr<tv::Recorder> recorder;  // declared last, destroyed first: it detaches
};

/// While recording: names the item at `itemIdx` (handle `id`) for the debugger (labels.cpp):
/// its `name` field, else its class's name and a serial ("Guardian 3"), else its
/// `type`/`kind`/`class` string field and a serial, else its Lua type and a serial
/// ("table 17"); the category from the class or those fields. Never an address.
void labelItem(lua_State* L, int worldIdx, LuaWorld& w, int itemIdx, tv::ItemId id);

/// Borrows the world's scratch for one call; the next nested call gets the next one.
class Lease {
 public:
  explicit Lease(LuaWorld& w) : w_(w) {
    if (w.scratchDepth == w.scratch.size()) w.scratch.push_back(std::make_unique<LuaWorld::Scratch>());
    s_ = w.scratch[w.scratchDepth++].get();
    s_->items.clear();
    s_->cols.clear();
  }
  ~Lease() { --w_.scratchDepth; }
  Lease(const Lease&) = delete;
  Lease& operator=(const Lease&) = delete;
  LuaWorld::Scratch* operator->() const { return s_; }

 private:
  LuaWorld& w_;
  LuaWorld::Scratch* s_;
};

/// Marks a world busy while its filters or responses may run: they must not change it.
class Busy {
 public:
  explicit Busy(LuaWorld& w) : w_(w) { ++w.busy; }
  ~Busy() { --w_.busy; }
  Busy(const Busy&) = delete;
  Busy& operator=(const Busy&) = delete;

 private:
  LuaWorld& w_;
};
/// Raises "world:<what> cannot be called while one of the world's filters or responses runs".
void checkNotBusy(lua_State* L, LuaWorld& w, const char* what);
/// The part of moveCells that needs no Lua: returns true when a cell emptied (the caller then
/// keeps the sentinel alive). `sentinelAlive` says whether no collection ran since the last one
/// emptied (asked only when a range changes).
template <class Alive>
bool relocateCells(LuaWorld& w, std::uint32_t slot, const tv::Rect* to, Alive sentinelAlive) {
  if (slot >= w.ranges.size()) w.ranges.resize(slot + 1);
  BumpCells::Range& from = w.ranges[slot];
  const BumpCells::Range b = to ? w.cells.of(*to) : BumpCells::Range{};
  if (to && from == b) return false;  // the usual small move: nothing to do
  if (to) w.cells.add(b);             // first, so that shared cells never empty
  bool emptied = false;
  if (from.x0 <= from.x1 && from.y0 <= from.y1) {
    // Cells emptied before a collection that has run since are gone, as in bump.
    if (!sentinelAlive()) w.cells.collect();
    emptied = w.cells.remove(from);
  }
  from = b;
  return emptied;
}
/// Moves the item in `slot` to `to` in bump's cells (null: removed); where it was is cached per
/// slot. Emptied cells stay counted until the next garbage collection, as bump's weak cell
/// tables do.
void moveCells(lua_State* L, int worldIdx, LuaWorld& w, std::uint32_t slot, const tv::Rect* to);
/// countCells: bump's cells, emptied ones included until they would have been collected.
std::size_t countBumpCells(lua_State* L, int worldIdx, LuaWorld& w);

/// The world at `idx`, or a Lua error "bad self: expected a world, got <value>".
LuaWorld& checkWorld(lua_State* L, int idx);
/// Pushes env[slot] of the world at `idx`.
void pushEnv(lua_State* L, int worldIdx, int slot);
/// The slot of the item at `itemIdx`, or -1 when it is not in the world. `mapIdx` is the
/// item -> slot table.
std::int64_t findSlot(lua_State* L, int mapIdx, int itemIdx);
/// An item argument: anything but nil and NaN.
void checkItem(lua_State* L, int idx);
/// The handle of the item at `itemIdx`; raises bump's "Item x must be added to the world
/// before <doing>. Use world:add(item, x,y,w,h) to add it first."
tv::ItemId requireItem(lua_State* L, LuaWorld& w, int worldIdx, int itemIdx, const char* doing);

/// The name of a response, for `col.type`.
void pushResponseName(lua_State* L, int worldIdx, tv::ResponseId id);
/// A filter's answer (on top of the stack, popped) as a response: nil/false -> ignore.
tv::ResponseId answerToResponse(lua_State* L, LuaWorld& w, int worldIdx);

/// Pushes a bump collision table for `c`; `itemIdx` is the mover (0: nil), `slotToItem` the
/// slot -> item table.
void pushCollision(lua_State* L, int worldIdx, int slotToItem, int itemIdx, const tv::Collision& c,
                   bool withTarget);

/// While a filter or response of a world runs: the Lua state, the world, and the stack slots of
/// the call's arguments. Responses added from Lua find it here: the core calls a response
/// through a plain function pointer, which has no room for a context.
struct CallContext {
  lua_State* L = nullptr;
  LuaWorld* world = nullptr;
  int worldIdx = 0;
  int itemIdx = 0;    // the mover (0 for project of nil)
  int filterIdx = 0;  // 0: no filter (everything slides)
  int slotToItem = 0;
  int savedCols = 0;  // 0: collision tables the responses see are not kept
  int responded = 0;  // responses run so far in this call
  // A move with bump's rules: the item's rect before it (what bump's responses receive as
  // x,y,w,h), and, while a response added from Lua runs, where it last projected the item from.
  bool bump = false;
  tv::ItemId item;  // the mover, when it is in the world
  tv::Rect origin;
  bool inResponse = false;
  bool projected = false;
  tv::Vec2 projectedFrom;
  CallContext* outer = nullptr;
};
/// Installs `c` as its world's current call until destroyed (nests: a filter may move the same
/// world or another). `c.world` must be set.
class CallScope {
 public:
  explicit CallScope(CallContext& c);
  ~CallScope();
  CallScope(const CallScope&) = delete;
  CallScope& operator=(const CallScope&) = delete;

 private:
  CallContext& c_;
};

/// The filter of a move, check or project: calls the Lua function `filter(item, other)` (or
/// answers slide for everything when there is none). A raising filter throws LuaRaised with
/// the error on the stack.
struct LuaFilter {
  CallContext* call;
  tv::ResponseId operator()(tv::ItemId item, tv::ItemId other) const;
};

/// The core response that runs a response added from Lua (bump's signature:
/// fn(world, col, x,y,w,h, goalX, goalY, filter) -> goalX, goalY); its context is the LuaWorld.
tv::Leg luaResponse(void* world, const tv::Collision& c, tv::Vec2 goal);

// Registration (module.cpp builds the tables from these).
void registerWorldMethods(lua_State* L, int methodsIdx);   // bump's World API
/// Under LuaJIT, replaces the hot methods in `methodsIdx` (getRect, move, check, go,
/// getCollision) by Lua functions over the FFI that fall back to the C functions they replace
/// (fast_path.cpp). Does nothing where `ffi` is missing or TV_LUA_FFI=0.
void installFastPath(lua_State* L, int methodsIdx);
/// Sets `fastPath` (true when installed) and `_capi` (the C functions the fast path replaced:
/// move, check, getRect, go, getCollision; nil without it) in the table at moduleIdx.
void pushFastPathInfo(lua_State* L, int moduleIdx);
/// Sets each of `fns` (ended by {nullptr, nullptr}) as a field of the table at `tableIdx` (an
/// absolute index): Lua 5.1 has no luaL_setfuncs.
inline void setFunctions(lua_State* L, int tableIdx, const luaL_Reg* fns) {
  for (const luaL_Reg* f = fns; f->name; ++f) {
    lua_pushcfunction(L, f->func);
    lua_setfield(L, tableIdx, f->name);
  }
}
void registerExtraMethods(lua_State* L, int methodsIdx);   // tunnelvision's additions
void registerPlatformMethods(lua_State* L, int methodsIdx);  // contacts, ground, moveCornered
void registerRecordingMethods(lua_State* L, int methodsIdx);  // startRecording, frame...
void pushValidateRecording(lua_State* L);                     // tunnelvision.validateRecording
void pushRecordingItems(lua_State* L);                        // tunnelvision.recordingItems
void pushRecordingNudges(lua_State* L);                       // tunnelvision.recordingNudges
void pushRectFunctions(lua_State* L);                      // bump.rect
void pushResponseFunctions(lua_State* L);                  // bump.responses
/// newWorld(cellSize): upvalue 1 is the methods table, 2 the collision keys, 3 true for bump's
/// rules, 4 the module's bump.responses.
int newWorld(lua_State* L);
/// The __index of a world's field table, for keys that are not methods: bump's `rows`,
/// `rects`, `nonEmptyCells` and `responses`, built when read (internals.cpp). Upvalue 1 is the
/// world.
int readInternals(lua_State* L);
/// Marks the world changed: its internal tables are rebuilt at their next read.
inline void touched(LuaWorld& w) { ++w.version; }
/// bump's `visitedFilter(item, other)` for the move that runs now (upvalue 1: the world).
int visitedFilter(lua_State* L);
/// Automatic recording (autorecord.cpp): starts recording a new world when `record` or
/// TV_RECORD asked for every world to be recorded. The world is at `worldIdx`.
void recordIfAsked(lua_State* L, int worldIdx, LuaWorld& w);
/// Puts `record`, `frame` and `stopRecording` into the `tunnelvision` table at moduleIdx.
void pushAutoRecord(lua_State* L, int moduleIdx);
/// TV_RECORD and TV_LIVE: turn automatic recording and the live stream on (once per Lua state)
/// when the variables are set; a path that cannot be written, or a TV_LIVE that is not an
/// address, is reported on stderr in one line naming the value, and the game runs on.
void recordFromEnvironment(lua_State* L);
bool isBuiltinResponse(lua_CFunction f, tv::ResponseId& id);

}  // namespace tvlua
