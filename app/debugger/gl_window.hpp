#pragma once
// The window: GLFW with an OpenGL 3.3 core context, and Dear ImGui's stock GLFW and OpenGL3
// backends (from Debian's libimgui.a) bound to it.

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace tv::viewer {

struct WindowConfig {
  int width = 1280, height = 720;
  std::string title = "Tunnelvision";
  /// Fixed size, no scaling to the monitor, no vsync: what a screenshot needs.
  bool exact = false;
};

/// A key went down (or repeated), with GLFW's key code and modifier bits.
struct KeyPress {
  int key = 0;
  int mods = 0;
};

class GlWindow {
 public:
  /// Opens the window and creates the ImGui context with both backends. Throws
  /// std::runtime_error when there is no display or no GL 3.3.
  explicit GlWindow(const WindowConfig& config);
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  [[nodiscard]] bool shouldClose() const;
  void requestClose();
  /// Takes events and starts an ImGui frame (platform and renderer backends; NewFrame is left
  /// to the caller, so it can pin input first). `idle`: nothing moves on screen, so wait for an
  /// event (or a short timeout, which lets ImGui settle hovers and popups) instead of spinning.
  void beginFrame(bool idle = false);
  /// Clears to `background`, draws ImGui's draw data.
  void render(std::uint32_t background);
  void swap();
  /// The back buffer as RGB rows, top row first (call after render, before swap).
  [[nodiscard]] std::vector<std::uint8_t> readRgb(int& width, int& height) const;
  /// The monitor's content scale (DPI / 96), >= 1 only where the system says so.
  [[nodiscard]] float contentScale() const;
  void windowSize(int& width, int& height) const;
  /// The keys pressed since the last call. ImGui 1.86 only sees whether a key is down at each
  /// frame, so a tap shorter than a frame would be lost; these are queued as they come.
  [[nodiscard]] std::vector<KeyPress> takeKeys();
  /// The paths of files dropped on the window since the last call.
  [[nodiscard]] std::vector<std::string> takeDrops();

 private:
  GLFWwindow* window_ = nullptr;
};

/// Writes an opaque RGB picture as PNG; throws std::runtime_error on failure.
void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace tv::viewer
