#pragma once
/// The camera: which world rect is on screen, and where. World coordinates are doubles that may
/// be far from the origin (scenes take an offset up to 1e9), so every transform subtracts the
/// view's corner in double first and only then narrows to ImGui's float.

#include "imgui.h"
#include "tv/geometry.hpp"

namespace tv::ui {

class Camera {
 public:
  Camera() = default;

  /// Shows `world` as large as fits in the screen rect (min, size), centred; the view grows
  /// along one axis to the screen's aspect, so nothing is stretched and nothing of `world` is
  /// cut. `world` must have w, h > 0.
  void frame(const Rect& world, ImVec2 screenMin, ImVec2 screenSize);
  /// The same, but `world` goes inside the part of the screen rect that nothing covers
  /// (`safeMin`, `safeSize`: e.g. between a HUD and a legend); the view still fills the screen.
  void frame(const Rect& world, ImVec2 screenMin, ImVec2 screenSize, ImVec2 safeMin,
             ImVec2 safeSize);
  /// Keeps the view's centre and scale, moves it to another screen rect (a resized window).
  void place(ImVec2 screenMin, ImVec2 screenSize);
  /// Multiplies the scale by `factor` (> 0), keeping the world point under `anchor` in place.
  void zoom(double factor, ImVec2 anchor);
  /// Moves the view by a screen-space drag.
  void pan(ImVec2 screenDelta);

  /// Screen pixels per world unit.
  [[nodiscard]] double scale() const { return scale_; }
  /// The world rect on screen (covers the whole screen rect).
  [[nodiscard]] const Rect& view() const { return view_; }
  [[nodiscard]] ImVec2 screenMin() const { return min_; }
  [[nodiscard]] ImVec2 screenMax() const { return {min_.x + size_.x, min_.y + size_.y}; }

  [[nodiscard]] ImVec2 toScreen(Vec2 p) const;
  /// Screen rect's corners (min, max).
  [[nodiscard]] ImVec2 toScreenMin(const Rect& r) const { return toScreen(r.position()); }
  [[nodiscard]] ImVec2 toScreenMax(const Rect& r) const {
    return toScreen({r.right(), r.bottom()});
  }
  [[nodiscard]] Vec2 toWorld(ImVec2 p) const;
  /// A length in world units, on screen.
  [[nodiscard]] float toScreenLength(double worldLength) const {
    return static_cast<float>(worldLength * scale_);
  }

  /// True when any part of the closed rect `r` is in view: everything else is skipped.
  [[nodiscard]] bool sees(const Rect& r) const;
  [[nodiscard]] bool sees(Vec2 p) const;

 private:
  Rect view_{0, 0, 1, 1};
  double scale_ = 1.0;
  ImVec2 min_{0, 0};
  ImVec2 size_{1, 1};
};

}  // namespace tv::ui
