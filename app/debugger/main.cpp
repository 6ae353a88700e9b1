// tv-debugger: the interactive debugger (GLFW, OpenGL 3.3, Dear ImGui's stock backends). Every
// picture is drawn by the drawing layer (tv::ui), the same code tv-render draws with; the
// smoke mode (--screenshot) draws tv-render's picture through this window, so a test can
// demand equal pixels from both.
#include <cfloat>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "debugger.hpp"
#include "gl_window.hpp"
#include "imgui.h"
#include "options.hpp"
#include "settings.hpp"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/still.hpp"

namespace tv::viewer {
namespace {

constexpr int kUsageExit = 2;
constexpr int kFailureExit = 1;

void printList() {
  std::cout << ui::sceneAndMoverList();
}

// Input that a screenshot must not see: the backend refreshes both every frame, so they are
// pinned after it and before NewFrame.
void pinInput() {
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = 1.0f / 60.0f;
  io.MousePos = {-FLT_MAX, -FLT_MAX};
}

void checkSize(const GlWindow& window, int width, int height) {
  int w = 0, h = 0;
  window.windowSize(w, h);
  if (w != width || h != height) {
    throw std::runtime_error("the window is " + std::to_string(w) + "x" + std::to_string(h) +
                             ", not the " + std::to_string(width) + "x" + std::to_string(height) +
                             " asked for (is the screen large enough?)");
  }
}

void scaleUi(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  ui::applyStyle(ImGui::GetStyle());
  if (scale == 1.0f) return;
  ImGui::GetStyle().ScaleAllSizes(scale);
  // The built-in font, rasterised at the scaled size rather than stretched, stays sharp.
  ImFontConfig font;
  font.SizePixels = std::round(13.0f * scale);
  io.Fonts->Clear();
  io.Fonts->AddFontDefault(&font);
}

// Smoke mode: tv-render's picture, through GLFW and GLX.
int screenshot(const ViewerOptions& o) {
  const ui::PictureOptions& p = o.picture;
  // A scene's still, or a recording's (tv-render --open).
  ui::Still still(p, o.recording);
  still.advanceTo(p.ticks.front(), "tv-debugger");
  GlWindow window({p.width, p.height, "Tunnelvision", true});
  checkSize(window, p.width, p.height);
  ImGui::GetIO().DisplaySize = {static_cast<float>(p.width), static_cast<float>(p.height)};
  scaleUi(1.0f);
  still.beginImage();
  for (int f = 0; f < p.frames; ++f) {
    window.beginFrame();
    pinInput();
    ImGui::NewFrame();
    still.drawFrame(ImGui::GetIO().DisplaySize);
    ImGui::Render();
    window.render(ui::palette::kBackground);
    if (f + 1 == p.frames) {
      int w = 0, h = 0;
      const auto rgb = window.readRgb(w, h);
      writePng(*o.screenshot, w, h, rgb);
    }
    window.swap();
  }
  std::cout << *o.screenshot << "\n";
  return 0;
}

int interactive(const ViewerOptions& o) {
  const bool shot = o.appScreenshot.has_value();
  const bool useSettings = !o.noSettings && !shot;
  const auto path = useSettings ? Settings::defaultPath() : std::nullopt;
  Settings settings;
  const bool loaded = path && settings.load(*path);
  ViewerOptions opening = o;
  ui::PictureOptions& p = opening.picture;
  if (!loaded && !shot && !o.recording && !p.sceneGiven && !p.moverGiven && !p.tickGiven) {
    // The first run opens on the moment that matters: the tick the naive bullet passes the
    // wall, followed, beside the substep patch and the exact sweep.
    p.scene = "bullets-wall";
    p.movers = {MoverSpec{.kind = MoverKind::discrete}, MoverSpec{.kind = MoverKind::substep},
                MoverSpec{.kind = MoverKind::continuous}};
    p.compare = true;
    p.ticks = {2};
    p.body = 2;
    p.view = ui::ViewKind::follow;
  }
  // Everything opens before the window does, so a bad file or flag fails without a display.
  Debugger debugger(opening, loaded ? &settings : nullptr);
  if (!loaded && !shot) debugger.openHelp();  // the first run opens Help
  debugger.setPinned(shot);
  WindowConfig config{o.picture.width, o.picture.height, "Tunnelvision debugger", shot};
  if (loaded && !o.picture.windowGiven) {
    config.width =
        static_cast<int>(std::clamp(settings.getNumber("window.width", 1280), 320.0, 8192.0));
    config.height =
        static_cast<int>(std::clamp(settings.getNumber("window.height", 720), 240.0, 8192.0));
  }
  GlWindow window(config);
  if (shot) checkSize(window, config.width, config.height);
  const float scale = o.uiScale > 0.0 ? static_cast<float>(o.uiScale)
                                      : (shot ? 1.0f : std::max(window.contentScale(), 1.0f));
  scaleUi(scale);
  debugger.setPinned(shot);


  auto last = std::chrono::steady_clock::now();
  for (int f = 0; !window.shouldClose() && !debugger.wantsQuit(); ++f) {
    window.beginFrame(!shot && debugger.idle());
    const auto now = std::chrono::steady_clock::now();
    double seconds = std::chrono::duration<double>(now - last).count();
    last = now;
    if (shot) {
      pinInput();
      seconds = 0.0;
    }
    // A recording opens in the recording view; anything else is a level (a map, a scene file).
    for (const std::string& dropped : window.takeDrops()) {
      if (dropped.ends_with(".tvrec")) {
        debugger.tryOpenRecording(dropped);
      } else {
        debugger.openFile(dropped);
      }
    }
    ImGui::NewFrame();
    debugger.frame(std::min(seconds, 0.25), window.takeKeys());
    ImGui::Render();
    window.render(ui::palette::kBackground);
    if (shot && f + 1 >= o.picture.frames) {
      int w = 0, h = 0;
      const auto rgb = window.readRgb(w, h);
      writePng(*o.appScreenshot, w, h, rgb);
      std::cout << *o.appScreenshot << "\n";
      break;
    }
    window.swap();
  }
  if (path) {
    debugger.store(settings);
    int w = 0, h = 0;
    window.windowSize(w, h);
    // Saved in screen coordinates, before the content scale, as glfwCreateWindow takes them.
    settings.setNumber("window.width", w);
    settings.setNumber("window.height", h);
    std::string error;
    if (!settings.save(*path, error))
      std::cerr << "tv-debugger: settings not saved: " << error << "\n";
  }
  return 0;
}

int run(int argc, char** argv) {
  const ViewerOptions o = parseViewerOptions(argc, argv);
  if (o.picture.help) {
    std::cout << kUsage;
    return 0;
  }
  if (o.picture.list) {
    printList();
    return 0;
  }
  return o.screenshot ? screenshot(o) : interactive(o);
}

}  // namespace
}  // namespace tv::viewer

int main(int argc, char** argv) {
  try {
    return tv::viewer::run(argc, argv);
  } catch (const tv::ui::UsageError& e) {
    std::cerr << "tv-debugger: " << e.message << "\n(see tv-debugger --help)\n";
    return tv::viewer::kUsageExit;
  } catch (const tv::ui::NoFailure& e) {
    std::cerr << "tv-debugger: " << e.message << ": nothing to show, no image written\n";
    return 0;
  } catch (const tv::Error& e) {
    // A file (map, scene file, recording) that cannot be read or used: the input, as in
    // tv-replay, tv-render and tv-run.
    std::cerr << "tv-debugger: " << tv::app::userMessage(e) << "\n";
    return tv::viewer::kUsageExit;
  } catch (const std::exception& e) {
    std::cerr << "tv-debugger: " << tv::app::userMessage(e) << "\n";
    return tv::viewer::kFailureExit;
  }
}
