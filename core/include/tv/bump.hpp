#pragma once
/// bump.lua 3.1.7's rules, as its source defines them, for games that were written against it
/// (the Lua module's `tunnelvision.bump`; any World move or check made with
/// `MoveOptions::semantics = MoveSemantics::bump`). One place holds them, so that every entry
/// point — the Lua C API, a LuaJIT FFI path, a replay, the debugger's traced re-run — gets the
/// same answers.
///
/// What bump does, and so what this does:
/// - `detect` is bump's `rect_detectCollision`, computed with the same double operations in the
///   same order (Liang-Barsky on the Minkowski difference, the 1e-10 margin, the corner rule), so
///   `ti`, `normal` and `touch` are bump's bit for bit. A rect starting inside another gets
///   `ti` = minus the area of the minimum displacement (`wi * hi` from the nearest corner of the
///   difference), a push out along that displacement when not moving (ties: the vertical way),
///   and a push back against its movement when moving.
/// - A move (`check`, then the item placed at the result) projects its straight leg, takes the
///   first collision in bump's order — `ti`, then the squared distance between centres — and
///   hands it to the response: touch stops at the contact; cross keeps the goal and projects
///   again from the move's start; slide keeps the goal on the axis along the surface and projects
///   from the contact; bounce reflects what is left of the move and projects from the contact.
///   Every item met is left out of the rest of the move (bump's `visited`).
/// - Candidates are the items registered in bump's cells (`floor(x / size) + 1` to
///   `ceil((x + w) / size)`) of the leg's bounding box.
///
/// Where bump leaves an order open, or where its rounding breaks a game, this decides — never
/// in a way a game that worked on bump could notice:
/// - collisions at the same `ti` and distance come in the order the items were added (bump: the
///   order of a Lua `pairs` over a table keyed by items, which follows memory addresses);
/// - a contact is never inside what it touched: where bump's `start + ti * move` rounds to a
///   point a step inside the other (what stops a body at a tile seam for good), the coordinate on
///   the normal's axis is placed against the other's edge instead (`placeBefore`); otherwise it
///   is bump's, bit for bit;
/// - a move never passes into something it already met and did not cross (bump lets a body that
///   bounces between two close walls through the first one on its second visit): a later leg
///   that would enter such an item — one the move did not start inside, and that the leg does
///   not start inside — ends the move at the contact with it, reported as one more collision
///   with the response its filter gave for it;
/// - the filter is asked only about items the leg actually hits, in bump's order, until one is
///   not ignored (bump asks about every candidate in the cells, in `pairs` order); a filter that
///   is a function of its pair sees no difference.

#include <span>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"
#include "tv/sweep.hpp"

namespace tv {

class World;
struct SegmentHit;

namespace bump {

/// bump's floating-point margin (its `DELTA`).
inline constexpr double kDelta = 1e-10;

/// bump's `rect_getSegmentIntersectionIndices`: the segment a→b clipped against `r` over the
/// parameter range [ti1, ti2], with the normals of the sides where it enters and leaves.
struct Indices {
  bool hit = false;  ///< false: bump returns nil
  double ti1 = 0.0;  ///< where the segment enters `r` (a fraction of a→b), at least ti1 given
  double ti2 = 0.0;  ///< where it leaves `r`, at most ti2 given
  /// The normal of the side it enters by; (0, 0) when it is inside `r` at the ti1 given.
  Vec2 normal1;
  /// The normal of the side it leaves by; (0, 0) when it is inside `r` at the ti2 given.
  Vec2 normal2;
};
[[nodiscard]] Indices segmentIndices(const Rect& r, Vec2 a, Vec2 b, double ti1, double ti2);

/// bump's `rect_getNearestCorner`: the corner of `r` nearest to p on each axis (on a tie, the
/// far one).
[[nodiscard]] Vec2 nearestCorner(const Rect& r, Vec2 p);
/// bump's `rect_containsPoint`: p inside `r` by more than kDelta on every side.
[[nodiscard]] bool containsPoint(const Rect& r, Vec2 p);
/// bump's `rect_getSquareDistance`: the squared distance between the centres.
[[nodiscard]] double squareDistance(const Rect& a, const Rect& b);
/// bump's `rect_isIntersecting` (open interiors).
[[nodiscard]] bool isIntersecting(const Rect& a, const Rect& b);

/// bump's `rect_detectCollision(item, other, goal)` with the contact kept out of `other` (see
/// above). `kind` miss is bump's nil.
[[nodiscard]] Sweep detect(const Rect& item, Vec2 goal, const Rect& other);

/// bump's cells of a rect (`grid_toCellRect`), 1-based as bump counts them: columns
/// [left, right], rows [top, bottom].
struct Cells {
  double left = 1.0;    ///< first column
  double top = 1.0;     ///< first row
  double right = 0.0;   ///< last column (below `left`: no cells)
  double bottom = 0.0;  ///< last row
  /// Whether the two ranges share a cell.
  [[nodiscard]] bool meets(const Cells& o) const {
    return left <= o.right && o.left <= right && top <= o.bottom && o.top <= bottom;
  }
};
[[nodiscard]] Cells cellsOf(double cellSize, const Rect& r);
/// The cells of a leg's bounding box, computed as bump's `World:project` does.
[[nodiscard]] Cells cellsOfLeg(double cellSize, const Rect& r, Vec2 goal);

/// bump's `World:project(item, x,y,w,h, goalX, goalY, filter)`: every collision of the straight
/// leg `r` → `goal` with an item other than `item` and those in `exclude`, in bump's order, each
/// with the response the filter chose (ignored pairs left out). The filter is asked about the
/// items hit, in that order. `item` may be invalid (a rect not in the world). Appends to `out`.
void project(const World& world, ItemId item, const Rect& r, Vec2 goal, Filter filter,
             std::span<const ItemId> exclude, std::vector<Collision>& out);

/// bump's `World:queryPoint`: items containing p by more than kDelta on every side, in add
/// order (bump: `pairs` order).
void queryPoint(const World& world, Vec2 p, std::vector<ItemId>& out);

/// bump's `World:querySegment(WithCoords)`: items whose rect the segment a→b enters or leaves
/// strictly between its ends (an item holding the whole segment is left out, as in bump), found
/// in the cells bump's traversal visits, sorted by where the infinite line enters them (ties in
/// add order). `t0`/`t1` are bump's `ti1`/`ti2`, `entry`/`exit` its `x1,y1`/`x2,y2`.
void querySegment(const World& world, Vec2 a, Vec2 b, std::vector<SegmentHit>& out);

}  // namespace bump
}  // namespace tv
