// The still picture shared by tv-render and tv-debugger's screenshot mode.
#include "tv/app/user_message.hpp"
#include "tv/ui/still.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>

#include "tv/app/flags.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/ui/layout.hpp"

namespace tv::ui {

namespace {

std::string compareTitle(const Session& s, const PictureOptions& o, std::uint64_t tick) {
  const sim::Params& p = s.sim().params();
  char text[512];
  std::snprintf(text, sizeof text,
                "%s at tick %llu   |   speed %g px/s, size %g px, tile %g px, dt %.2f ms, "
                "max substep %s   |   traced: %s",
                o.scene.c_str(), static_cast<unsigned long long>(tick), p.get(sim::param::speed),
                p.get(sim::param::size), p.get(sim::param::tile), p.get(sim::param::dt) * 1000.0,
                p.get(sim::param::substep) == 0.0
                    ? "tile/2"
                    : (formatNumber(p.get(sim::param::substep)) + " px").c_str(),
                o.body ? ("body " + std::to_string(*o.body)).c_str() : "none");
  return text;
}

Rect viewFor(const PictureOptions& o, const std::vector<std::unique_ptr<Session>>& sessions) {
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

}  // namespace

const sim::SceneDef& sceneFor(const PictureOptions& o) {
  if (o.file.given()) return o.file.scene();  // tv::Error naming the file, path and value
  if (const sim::SceneDef* s = sim::builtinScenes().tryFind(o.scene)) return *s;
  std::string valid;
  for (const std::string_view n : sim::builtinScenes().names()) {
    valid += (valid.empty() ? "" : ", ") + std::string(n);
  }
  throw UsageError{"--scene: no scene is named '" + o.scene + "'; valid: " + valid};
}

sim::Params paramsFor(const sim::SceneDef& scene, const PictureOptions& o) {
  sim::Params p = scene.defaults();
  for (const auto& [name, text] : o.params) {
    const std::string flag = "--" + name;
    if (!p.has(name)) {
      std::string valid;
      for (const std::string_view n : p.names())
        valid += (valid.empty() ? "--" : ", --") + std::string(n);
      throw UsageError{flag + ": neither a flag nor a parameter of scene '" + scene.name +
                       "' (its parameters: " + valid + ")"};
    }
    // Read as every tool reads a number (tv/app/flags.hpp): the same message everywhere.
    const double v = app::parseFinite<UsageError>(name, text);
    try {
      p.set(name, v);
    } catch (const Error& e) {
      throw UsageError{flag + " " + text + ": " + app::userMessage(e)};
    }
  }
  return p;
}

Overlays overlaysFor(const PictureOptions& o) {
  Overlays on;
  const auto apply = [&](const std::vector<std::string>& names, bool value, const char* flag) {
    for (const std::string& n : names) {
      bool found = n == "all";
      for (const OverlayToggle& t : overlayToggles()) {
        if (found && n == "all") on.*t.flag = value;
        if (n == t.name) {
          on.*t.flag = value;
          found = true;
        }
      }
      if (!found) {
        std::string valid;
        for (const OverlayToggle& t : overlayToggles()) valid += std::string(" ") + t.name;
        throw UsageError{std::string(flag) + ": no overlay is named '" + n + "'; valid: all" +
                         valid};
      }
    }
  };
  apply(o.hide, false, "--hide");
  apply(o.show, true, "--show");
  return on;
}

Still::Still(const PictureOptions& o) : o_(o), scene_(&sceneFor(o)) {
  const sim::Params params = paramsFor(*scene_, o);
  (void)overlaysFor(o);  // a bad --hide/--show fails before anything runs
  for (const MoverSpec& spec : o.movers) {
    try {
      sessions_.push_back(std::make_unique<Session>(*scene_, params, spec, std::nullopt));
    } catch (const Error& e) {
      throw UsageError{"scene '" + scene_->name + "': " + app::userMessage(e)};
    }
    const sim::Simulation& sim = sessions_.back()->sim();
    if (auto why = app::workLimitExceeded(params, sim.moverSpec(), sim.bodies().size()))
      throw UsageError{*why};
    try {
      sessions_.back()->select(o.body);
    } catch (const Error& e) {
      throw UsageError{"--body: " + app::userMessage(e)};
    }
  }
  for (auto& s : sessions_) raw_.push_back(s.get());
}

void Still::advanceTo(std::uint64_t tick) {
  try {
    // First as far as the scene goes: a tick after every mover's end is refused, not run for
    // ever; a mover that ended early then runs on to the tick the others reach.
    std::uint64_t reached = 0;
    for (auto& s : sessions_) {
      s->advanceTo(tick, o_.renderHz, true);
      reached = std::max(reached, s->sim().ticks());
    }
    if (reached < tick) {
      throw UsageError{"--tick " + std::to_string(tick) + ": the scene ends at tick " +
                       std::to_string(reached)};
    }
    for (auto& s : sessions_) s->advanceTo(tick, o_.renderHz);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError{"--tick " + std::to_string(tick) + ": " + app::userMessage(e)};
  }
}

void Still::beginImage() {
  const Rect view = viewFor(o_, sessions_);
  states_.assign(sessions_.size(), DebuggerState{});
  for (std::size_t k = 0; k < sessions_.size(); ++k) {
    states_[k].overlays = overlaysFor(o_);
    states_[k].frameView = view;
    states_[k].renderHz = o_.renderHz;
    states_[k].paused = true;  // a still is a paused frame
    syncDraft(states_[k], *sessions_[k]);
  }
  title_ = o_.compare ? compareTitle(*sessions_.front(), o_, sessions_.front()->sim().ticks()) : "";
  if (o_.compare && !o_.caption.empty()) title_ += "\n" + o_.caption;
}

void Still::drawFrame(ImVec2 display) {
  ImGui::SetWindowFocus(nullptr);  // a still has no focused window: no highlighted title
  if (o_.compare) {
    comparisonLayout(raw_, states_, title_, display);
  } else {
    (void)debuggerLayout(*sessions_.front(), states_.front(), display);
  }
}

}  // namespace tv::ui
