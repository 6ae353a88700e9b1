#include "tv/response.hpp"

namespace tv {

Leg touchResponse(const Collision& c, Vec2 /*goal*/) {
  return {c.touch, c.touch};
}

Leg crossResponse(const Collision& c, Vec2 goal) {
  return {c.itemRect.position(), goal, /*passThrough=*/true};
}

Leg slideResponse(const Collision& c, Vec2 goal) {
  // Keep the motion along the surface; the normal's axis stays on the placed edge, so the next
  // leg runs exactly along it and a neighbouring tile's face is never entered.
  if (c.normal.x != 0.0) return {c.touch, {c.touch.x, goal.y}};
  return {c.touch, {goal.x, c.touch.y}};
}

Leg bounceResponse(const Collision& c, Vec2 goal) {
  // Reflect only what still points into the obstacle (a leg that started overlapping may
  // already be leaving it).
  Vec2 rest = goal - c.touch;
  if (c.normal.x * rest.x < 0.0) rest.x = -rest.x;
  if (c.normal.y * rest.y < 0.0) rest.y = -rest.y;
  return {c.touch, c.touch + rest};
}

Leg onewayResponse(const Collision& c, Vec2 goal) {
  return onewayBlocks(c) ? slideResponse(c, goal) : crossResponse(c, goal);
}

}  // namespace tv

namespace tv {

Vec2 keepVelocity(Vec2 v, const Collision& /*c*/) {
  return v;
}

Vec2 onewayVelocity(Vec2 v, const Collision& c) {
  return onewayBlocks(c) ? slideVelocity(v, c) : v;
}

Vec2 stopVelocity(Vec2 /*v*/, const Collision& /*c*/) {
  return {};
}

Vec2 slideVelocity(Vec2 v, const Collision& c) {
  if (v.x * c.normal.x < 0.0) v.x = 0.0;
  if (v.y * c.normal.y < 0.0) v.y = 0.0;
  return v;
}

Vec2 reflectVelocity(Vec2 v, const Collision& c) {
  if (v.x * c.normal.x < 0.0) v.x = -v.x;
  if (v.y * c.normal.y < 0.0) v.y = -v.y;
  return v;
}

}  // namespace tv
