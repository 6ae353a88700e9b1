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
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/layout.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/session.hpp"

namespace tv::headless {
namespace {

constexpr int kUsageExit = 2;
constexpr int kFailureExit = 1;

// [SECTION] --list -----------------------------------------------------------------------------

void printList() {
  std::cout << "scenes:\n";
  for (const sim::SceneDef& s : sim::builtinScenes().all()) {
    std::printf("  %-16s %s\n", s.name.c_str(), s.description.c_str());
  }
  std::cout << "movers:\n";
  for (const std::string_view m : moverNames()) {
    std::printf("  %-16s %s\n", std::string(m).c_str(), std::string(moverDescription(m)).c_str());
  }
}

// [SECTION] setting up from the options ---------------------------------------------------------

const sim::SceneDef& sceneFor(const Options& o) {
  if (const sim::SceneDef* s = sim::builtinScenes().tryFind(o.scene)) return *s;
  std::string valid;
  for (const std::string_view n : sim::builtinScenes().names()) {
    valid += (valid.empty() ? "" : ", ") + std::string(n);
  }
  throw UsageError{"--scene: no scene is named '" + o.scene + "'; valid: " + valid};
}

sim::Params paramsFor(const sim::SceneDef& scene, const Options& o) {
  sim::Params p = scene.defaults();
  for (const auto& [name, text] : o.params) {
    const std::string flag = "--" + (name == "size" ? std::string("body-size") : name);
    if (!p.has(name)) {
      std::string valid;
      for (const std::string_view n : p.names()) {
        if (n != "size") valid += (valid.empty() ? "--" : ", --") + std::string(n);
      }
      throw UsageError{flag + ": not a flag of tv-render nor a parameter of scene '" + scene.name +
                       "' (its parameters: " + valid + ", --body-size)"};
    }
    double v = 0.0;
    std::size_t used = 0;
    try {
      v = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size()) {
      throw UsageError{flag + ": expected a number, but got '" + text + "'"};
    }
    try {
      p.set(name, v);
    } catch (const Error& e) {
      throw UsageError{flag + " " + text + ": " + e.what()};
    }
  }
  return p;
}

ui::Overlays overlaysFor(const Options& o) {
  ui::Overlays on;
  const auto apply = [&](const std::vector<std::string>& names, bool value, const char* flag) {
    for (const std::string& n : names) {
      bool found = n == "all";
      for (const ui::OverlayToggle& t : ui::overlayToggles()) {
        if (found && n == "all") on.*t.flag = value;
        if (n == t.name) {
          on.*t.flag = value;
          found = true;
        }
      }
      if (!found) {
        std::string valid;
        for (const ui::OverlayToggle& t : ui::overlayToggles()) valid += std::string(" ") + t.name;
        throw UsageError{std::string(flag) + ": no overlay is named '" + n + "'; valid: all" +
                         valid};
      }
    }
  };
  apply(o.hide, false, "--hide");
  apply(o.show, true, "--show");
  return on;
}

std::string outputName(const Options& o, std::uint64_t tick) {
  std::string name;
  if (o.out) {
    name = *o.out;
  } else {
    std::string movers;
    for (const std::string& m : o.movers) movers += (movers.empty() ? "" : "-vs-") + m;
    name = o.scene + "_" + movers + "_{tick}.png";
  }
  for (std::size_t at; (at = name.find("{tick}")) != std::string::npos;) {
    name.replace(at, 6, std::to_string(tick));
  }
  return name;
}

// [SECTION] one image --------------------------------------------------------------------------

std::string compareTitle(const ui::Session& s, const Options& o, std::uint64_t tick) {
  const sim::Params& p = s.sim().params();
  char text[512];
  std::snprintf(text, sizeof text,
                "%s at tick %llu   |   velocity %g px/s, body %g px, tile %g px, dt %.2f ms, "
                "max substep %s   |   traced: %s",
                o.scene.c_str(), static_cast<unsigned long long>(tick), p.get(sim::param::speed),
                p.get(sim::param::size), p.get(sim::param::tile), p.get(sim::param::dt) * 1000.0,
                p.get(sim::param::substep) == 0.0
                    ? "tile/2"
                    : (formatNumber(p.get(sim::param::substep)) + " px").c_str(),
                o.body ? ("body " + std::to_string(*o.body)).c_str() : "none");
  return text;
}

Rect viewFor(const Options& o, const std::vector<std::unique_ptr<ui::Session>>& sessions) {
  const sim::Params& p = sessions.front()->sim().params();
  switch (o.view) {
    case ViewKind::scene:
      return sessions.front()->sim().camera();
    case ViewKind::rect:
      return {o.viewRect[0], o.viewRect[1], o.viewRect[2], o.viewRect[3]};
    case ViewKind::follow: {
      // One rect for every panel, so the movers are compared over the same ground.
      const double minSide = 4.0 * std::max(p.get(sim::param::tile), p.get(sim::param::size));
      Rect r = sessions.front()->followView(minSide);
      for (const auto& s : sessions) r = unite(r, s->followView(minSide));
      return r;
    }
  }
  return sessions.front()->sim().camera();
}

struct FrameTimes {
  double meanMs = 0.0;  // steady-state frames (the first, with cold shaders, left out)
  double uiMs = 0.0;    // of which building the UI (ImGui, on the CPU); the rest is GL
  double firstMs = 0.0;
};

FrameTimes renderImage(const Options& o, std::vector<std::unique_ptr<ui::Session>>& sessions,
                       std::uint64_t tick) {
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

  const Rect view = viewFor(o, sessions);
  std::vector<ui::DebuggerState> states(sessions.size());
  for (std::size_t k = 0; k < sessions.size(); ++k) {
    states[k].overlays = overlaysFor(o);
    states[k].frameView = view;
    states[k].renderHz = o.renderHz;
    states[k].paused = true;  // a still is a paused frame
    ui::syncDraft(states[k], *sessions[k]);
  }
  std::vector<ui::Session*> raw;
  for (auto& s : sessions) raw.push_back(s.get());
  const std::string title = o.compare ? compareTitle(*sessions.front(), o, tick) : "";

  FrameTimes times;
  for (int f = 0; f < o.frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    ImGui::SetWindowFocus(nullptr);  // a still has no focused window: no highlighted title
    if (o.compare) {
      ui::comparisonLayout(raw, states, title, io.DisplaySize);
    } else {
      (void)ui::debuggerLayout(*sessions.front(), states.front(), io.DisplaySize);
    }
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

int run(int argc, char** argv) {
  const Options o = parseOptions(argc, argv);
  if (o.help) {
    std::cout << kUsage;
    return 0;
  }
  if (o.list) {
    printList();
    return 0;
  }
  const sim::SceneDef& scene = sceneFor(o);
  const sim::Params params = paramsFor(scene, o);
  std::vector<std::unique_ptr<ui::Session>> sessions;
  for (const std::string& m : o.movers) {
    MoverSpec spec;
    try {
      spec = parseMover(m);
    } catch (const Error& e) {
      throw UsageError{std::string(o.compare ? "--compare" : "--mover") + ": " + e.what()};
    }
    try {
      sessions.push_back(std::make_unique<ui::Session>(scene, params, spec, std::nullopt));
    } catch (const Error& e) {
      throw UsageError{"scene '" + scene.name + "': " + e.what()};
    }
    try {
      sessions.back()->select(o.body);
    } catch (const Error& e) {
      throw UsageError{"--body: " + std::string(e.what())};
    }
  }

  OffscreenGl gl(o.width, o.height);
  for (const std::uint64_t tick : o.ticks) {
    for (auto& s : sessions) {
      try {
        s->advanceTo(tick, o.renderHz);
      } catch (const Error& e) {
        throw UsageError{"--tick " + std::to_string(tick) + ": " + e.what()};
      }
    }
    const FrameTimes t = renderImage(o, sessions, tick);
    const auto e0 = std::chrono::steady_clock::now();
    const std::string path = outputName(o, tick);
    writePng(path, o.width, o.height, gl.readRgb());
    const double pngMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
    std::cout << path << "\n";
    if (o.timing) {
      std::fprintf(stderr,
                   "tv-render: %dx%d, %d frames: first %.1f ms, then %.2f ms per frame (%.2f ms "
                   "building the UI, %.2f ms drawing it); PNG %.1f ms\n",
                   o.width, o.height, o.frames, t.firstMs, t.meanMs, t.uiMs, t.meanMs - t.uiMs,
                   pngMs);
    }
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
  } catch (const std::exception& e) {
    std::cerr << "tv-render: " << e.what() << "\n";
    return tv::headless::kFailureExit;
  }
}
