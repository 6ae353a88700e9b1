#include "tv/ui/camera.hpp"

#include <algorithm>

namespace tv::ui {

namespace {
// ImGui works in float; the camera's arithmetic is in double (see the header).
constexpr double dbl(float f) {
  return static_cast<double>(f);
}
}  // namespace

void Camera::frame(const Rect& world, ImVec2 screenMin, ImVec2 screenSize) {
  frame(world, screenMin, screenSize, screenMin, screenSize);
}

void Camera::frame(const Rect& world, ImVec2 screenMin, ImVec2 screenSize, ImVec2 safeMin,
                   ImVec2 safeSize) {
  min_ = screenMin;
  size_ = {std::max(screenSize.x, 1.0f), std::max(screenSize.y, 1.0f)};
  const double sw = std::max(dbl(safeSize.x), 1.0), sh = std::max(dbl(safeSize.y), 1.0);
  scale_ = std::min(sw / world.w, sh / world.h);
  // The world's centre lands on the safe area's centre.
  const Vec2 c = world.center();
  const double cx = dbl(safeMin.x - min_.x) + sw * 0.5, cy = dbl(safeMin.y - min_.y) + sh * 0.5;
  view_ = {c.x - cx / scale_, c.y - cy / scale_, dbl(size_.x) / scale_, dbl(size_.y) / scale_};
}

void Camera::place(ImVec2 screenMin, ImVec2 screenSize) {
  min_ = screenMin;
  size_ = {std::max(screenSize.x, 1.0f), std::max(screenSize.y, 1.0f)};
  const Vec2 c = view_.center();
  const double w = dbl(size_.x) / scale_, h = dbl(size_.y) / scale_;
  view_ = {c.x - w * 0.5, c.y - h * 0.5, w, h};
}

void Camera::zoom(double factor, ImVec2 anchor) {
  const Vec2 fixed = toWorld(anchor);
  scale_ *= factor;
  const double ax = dbl(anchor.x - min_.x), ay = dbl(anchor.y - min_.y);
  view_ = {fixed.x - ax / scale_, fixed.y - ay / scale_, dbl(size_.x) / scale_,
           dbl(size_.y) / scale_};
}

void Camera::pan(ImVec2 d) {
  view_.x -= dbl(d.x) / scale_;
  view_.y -= dbl(d.y) / scale_;
}

ImVec2 Camera::toScreen(Vec2 p) const {
  return {min_.x + static_cast<float>((p.x - view_.x) * scale_),
          min_.y + static_cast<float>((p.y - view_.y) * scale_)};
}

Vec2 Camera::toWorld(ImVec2 p) const {
  return {view_.x + dbl(p.x - min_.x) / scale_, view_.y + dbl(p.y - min_.y) / scale_};
}

bool Camera::sees(const Rect& r) const {
  return r.x <= view_.right() && view_.x <= r.right() && r.y <= view_.bottom() &&
         view_.y <= r.bottom();
}

bool Camera::sees(Vec2 p) const {
  return view_.x <= p.x && p.x <= view_.right() && view_.y <= p.y && p.y <= view_.bottom();
}

}  // namespace tv::ui
