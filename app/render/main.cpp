// tv-render: the debugger's picture of a scene at a tick, as a PNG, with no display — OSMesa
// (llvmpipe) draws Dear ImGui's output into memory and stb writes it. Links neither libGL nor
// GLFW. Deterministic: fixed DeltaTime, no ini file, no input, nothing read from a clock is
// drawn, and a fresh ImGui context per image, so an image never depends on the one before.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <GL/gl.h>

#include "backends/imgui_impl_opengl3.h"
#include "imgui.h"
#include "offscreen_gl.hpp"
#include "options.hpp"
#include "png.hpp"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/still.hpp"

namespace tv::headless {
namespace {

constexpr int kUsageExit = 2;
constexpr int kFailureExit = 1;

// [SECTION] --list -----------------------------------------------------------------------------

void printList() {
  std::cout << ui::sceneAndMoverList();
}

// [SECTION] file names ----------------------------------------------------------------------

std::string outputName(const Options& o, std::uint64_t tick) {
  std::string name;
  if (o.out) {
    name = *o.out;
  } else {
    std::string movers;
    for (const MoverSpec& m : o.movers) movers += (movers.empty() ? "" : "-vs-") + m.name();
    name = o.scene + "_" + movers + "_{tick}.png";
  }
  for (std::size_t at; (at = name.find("{tick}")) != std::string::npos;) {
    name.replace(at, 6, std::to_string(tick));
  }
  return name;
}

// [SECTION] one image --------------------------------------------------------------------------

struct FrameTimes {
  double meanMs = 0.0;  // steady-state frames (the first, with cold shaders, left out)
  double uiMs = 0.0;    // of which building the UI (ImGui, on the CPU); the rest is GL
  double firstMs = 0.0;
};

FrameTimes renderImage(const Options& o, ui::Still& still) {
  // A fresh context per image: window sizes, table widths and tree states never leak from one
  // picture into the next.
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  io.DisplaySize = {static_cast<float>(o.width), static_cast<float>(o.height)};
  io.DeltaTime = 1.0f / 60.0f;
  ui::applyStyle(ImGui::GetStyle());
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext();
    throw std::runtime_error("the OpenGL3 ImGui backend failed to initialise on OSMesa");
  }

  still.beginImage();

  FrameTimes times;
  for (int f = 0; f < o.frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    still.drawFrame(io.DisplaySize);
    ImGui::Render();
    const auto t1 = std::chrono::steady_clock::now();
    glViewport(0, 0, o.width, o.height);
    const ImVec4 bg = ImGui::ColorConvertU32ToFloat4(ui::palette::kBackground);
    glClearColor(bg.x, bg.y, bg.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f == 0) {
      times.firstMs = ms;
    } else {
      times.meanMs += ms / (o.frames - 1);
      times.uiMs += std::chrono::duration<double, std::milli>(t1 - t0).count() / (o.frames - 1);
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
  return times;
}

void report(const Options& o, const std::string& path, const FrameTimes& t, double pngMs) {
  std::cout << path << "\n";
  if (o.timing) {
    std::fprintf(stderr,
                 "tv-render: %dx%d, %d frames: first %.1f ms, then %.2f ms per frame (%.2f ms "
                 "building the UI, %.2f ms drawing it); PNG %.1f ms\n",
                 o.width, o.height, o.frames, t.firstMs, t.meanMs, t.uiMs, t.meanMs - t.uiMs,
                 pngMs);
  }
}

// --open FILE: a recorded game at a frame (and call), as tv-debugger shows it.
int renderRecording(const ui::RecordingFlags& r, const Options& o) {
  ui::Still still(o, r);
  OffscreenGl gl(o.width, o.height);
  const FrameTimes t = renderImage(o, still);
  const auto e0 = std::chrono::steady_clock::now();
  std::string path = o.out ? *o.out : std::string();
  if (path.empty()) {
    const std::string name = still.session().primary().name();
    path = name.substr(0, name.rfind('.')) + "_{tick}.png";
  }
  // The frame shown: --frame, or with --first-failure the frame it found.
  for (std::size_t at; (at = path.find("{tick}")) != std::string::npos;)
    path.replace(at, 6, std::to_string(still.session().frame()));
  writePng(path, o.width, o.height, gl.readRgb());
  const double pngMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
  report(o, path, t, pngMs);
  return 0;
}

int run(int argc, char** argv) {
  std::vector<char*> args;
  const auto recording = ui::extractRecordingFlags(argc, argv, false, args);
  Options o = parseOptions(static_cast<int>(args.size()), args.data());
  if (o.help) {
    std::cout << kUsage;
    return 0;
  }
  if (o.list) {
    printList();
    return 0;
  }
  if (recording) return renderRecording(*recording, o);
  if (o.file.given()) {
    for (const std::string& note : o.file.notes()) std::cerr << "tv-render: note: " << note << "\n";
    // The file's own mover (a scene file's "mover", a map's mover property) unless one was given.
    if (const auto m = o.file.mover(); m && !o.moverGiven) o.movers = {*m};
  }
  ui::Still still(o);
  OffscreenGl gl(o.width, o.height);
  // --first-failure: one image, at the tick the failure is in.
  const std::vector<std::uint64_t> ticks =
      still.failureShown() ? std::vector<std::uint64_t>{still.session().frame()} : o.ticks;
  for (const std::uint64_t tick : ticks) {
    still.advanceTo(tick);
    const FrameTimes t = renderImage(o, still);
    const auto e0 = std::chrono::steady_clock::now();
    const std::string path = outputName(o, tick);
    writePng(path, o.width, o.height, gl.readRgb());
    const double pngMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
    report(o, path, t, pngMs);
  }
  return 0;
}

}  // namespace
}  // namespace tv::headless

int main(int argc, char** argv) {
  try {
    return tv::headless::run(argc, argv);
  } catch (const tv::headless::UsageError& e) {
    std::cerr << "tv-render: " << e.message << "\n(see tv-render --help)\n";
    return tv::headless::kUsageExit;
  } catch (const tv::ui::NoFailure& e) {
    // Nothing failed, so there is no moment to draw: said, and not an error.
    std::cerr << "tv-render: " << e.message << ": nothing to show, no image written\n";
    return 0;
  } catch (const tv::Error& e) {
    // A file (map, scene file, recording) that cannot be read or used: the input, not the
    // rendering, as in tv-replay, tv-debugger and tv-run.
    std::cerr << "tv-render: " << tv::app::userMessage(e) << "\n";
    return tv::headless::kUsageExit;
  } catch (const std::exception& e) {
    std::cerr << "tv-render: " << tv::app::userMessage(e) << "\n";
    return tv::headless::kFailureExit;
  }
}
