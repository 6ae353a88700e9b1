#pragma once
/// The calls a recording holds, listed once. The CallKind enumerators (and so their codes in the
/// file: FORMAT.md, the low 4 bits of a call's kind byte), the names the tools print, the words
/// the debugger shows and what each call is for (which the replay's statistics, the live
/// stream's counters and the debugger's choice of traced calls read) all expand this list.
/// The decoder, the replay and the call summaries switch over CallKind with no default case, so a
/// new entry does not compile until each of them handles it. A new call is appended (the codes of
/// the others are the file format); kinds from 15 on are written as the code 15 and a varint.

#include <cstddef>
#include <cstdint>
#include <string_view>

// X(kind, role, words): `kind` is the enumerator and the name tools print; `role` a CallRole;
// `words` the call as the game wrote it, for the debugger's call list.
#define TV_RECORDED_CALLS(X)                             \
  X(add, ::tv::CallRole::item, "add")                    \
  X(remove, ::tv::CallRole::item, "remove")              \
  X(update, ::tv::CallRole::item, "update")              \
  X(move, ::tv::CallRole::move, "move")                  \
  X(check, ::tv::CallRole::sweep, "check")               \
  X(project, ::tv::CallRole::sweep, "project")           \
  X(queryRect, ::tv::CallRole::query, "queryRect")       \
  X(queryPoint, ::tv::CallRole::query, "queryPoint")     \
  X(querySegment, ::tv::CallRole::query, "querySegment") \
  X(anyOverlap, ::tv::CallRole::query, "anyOverlap")     \
  X(addResponse, ::tv::CallRole::setup, "addResponse")   \
  X(moverMove, ::tv::CallRole::move, "Mover::move")      \
  X(batchStep, ::tv::CallRole::batch, "Batch::step")     \
  X(label, ::tv::CallRole::note, "label")                \
  X(advance, ::tv::CallRole::note, "advance")            \
  X(contacts, ::tv::CallRole::query, "Contacts::update") \
  X(cornerNudge, ::tv::CallRole::note, "moveCornered")

namespace tv {

/// What a recorded call is for.
enum class CallRole : std::uint8_t {
  item,   ///< adds, removes or changes an item without a sweep (add, remove, update)
  move,   ///< moves one item by a sweep (World::move, Mover::move)
  sweep,  ///< one sweep that moves nothing (check, project)
  batch,  ///< moves many items (Batch::step)
  query,  ///< asks about the world (queryRect, queryPoint, querySegment, anyOverlap, contacts)
  setup,  ///< changes how later calls behave (addResponse)
  /// says something about the game and changes no item (label, advance: a frame's start,
  /// cornerNudge: the moves before it were a corner correction)
  note,
};

/// What a recorded call was: a World call (add ... anyOverlap, addResponse), a Mover::move, a
/// Batch::step, a Recorder::label, a FixedStep advance (a frame's start), a Contacts::update
/// (or forget) or a corner nudge (tv::moveCornered's, after the World calls that made it).
enum class CallKind : std::uint8_t {
#define TV_CALL_KIND(kind, role, words) kind,
  TV_RECORDED_CALLS(TV_CALL_KIND)
#undef TV_CALL_KIND
};

/// How many call kinds there are (CallKind's values are 0 .. kCallKindCount - 1).
inline constexpr std::size_t kCallKindCount = 0
#define TV_CALL_COUNT(kind, role, words) +1
    TV_RECORDED_CALLS(TV_CALL_COUNT)
#undef TV_CALL_COUNT
    ;

namespace detail {
struct CallDef {
  std::string_view name;
  CallRole role;
  std::string_view words;
};
inline constexpr CallDef kCalls[] = {
#define TV_CALL_DEF(kind, role, words) {#kind, role, words},
    TV_RECORDED_CALLS(TV_CALL_DEF)
#undef TV_CALL_DEF
};
}  // namespace detail

/// The call kind as the tools print it: "move", "queryRect", "moverMove"...
[[nodiscard]] constexpr std::string_view callKindName(CallKind k) {
  const auto i = static_cast<std::size_t>(k);
  return i < kCallKindCount ? detail::kCalls[i].name : "unknown";
}
/// What the call is for (CallRole::note for a value outside the list).
[[nodiscard]] constexpr CallRole callRole(CallKind k) {
  const auto i = static_cast<std::size_t>(k);
  return i < kCallKindCount ? detail::kCalls[i].role : CallRole::note;
}
/// The call as the game wrote it: "move", "Mover::move", "Batch::step"...
[[nodiscard]] constexpr std::string_view callWords(CallKind k) {
  const auto i = static_cast<std::size_t>(k);
  return i < kCallKindCount ? detail::kCalls[i].words : "unknown";
}
/// True for the calls that are one sweep, which the debugger can trace: move, check, project,
/// Mover::move.
[[nodiscard]] constexpr bool isOneSweep(CallKind k) {
  return callRole(k) == CallRole::move || callRole(k) == CallRole::sweep;
}

}  // namespace tv
