// The Open dialogs as a person types into them: a path typed after a failed one replaces it,
// and the error about the old path goes once the path is changed.
#include <filesystem>

#include "driver.hpp"

namespace tv::viewer {
namespace {

class OpenDialogs : public DebuggerDriver {
 protected:
  void SetUp() override {
    DebuggerDriver::SetUp();
    // The driver has no backend: Enter is mapped here as the GLFW backend maps it.
    ImGui::GetIO().KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
    folder_ = ::testing::TempDir() + "tv_open_dialogs_" + std::to_string(::getpid());
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override {
    std::filesystem::remove_all(folder_);
    DebuggerDriver::TearDown();
  }
  void type(const std::string& text) {
    for (const char c : text)
      ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(static_cast<unsigned char>(c)));
    frames(1);
  }
  void enter() {
    ImGui::GetIO().KeysDown[GLFW_KEY_ENTER] = true;
    frames(1);
    ImGui::GetIO().KeysDown[GLFW_KEY_ENTER] = false;
    frames(2);
  }
  void click(ImVec2 at) {
    ImGuiIO& io = ImGui::GetIO();
    io.MouseDown[0] = true;
    frame(at);
    io.MouseDown[0] = false;
    frame(at);
  }
  // Where the Open scene or level popup's path field is: the mouse is moved down its left side
  // until ImGui says the field is hovered.
  ImVec2 pathField() {
    const ImGuiWindow* w = ImGui::FindWindowByName("Open scene or level");
    if (!w) return {-1.0f, -1.0f};
    const ImGuiID id = const_cast<ImGuiWindow*>(w)->GetIDNoKeepAlive("##path");
    const ImRect r = w->Rect();
    for (float y = r.Max.y - 2.0f; y > r.Min.y; y -= 3.0f) {
      const ImVec2 at{r.Min.x + 60.0f, y};
      frame(at);
      if (GImGui->HoveredId == id) return at;
    }
    return {-1.0f, -1.0f};
  }
  std::string folder_;  // a folder: what a person gives by mistake
};

// Ctrl+R, "/tmp", Enter: refused. Ctrl+R again and the path typed was appended to "/tmp":
// "cannot open '/tmp/tmp/fe2/cut.tvrec'". The old path is now selected, and typing replaces it.
TEST_F(OpenDialogs, ARecordingPathTypedAfterAFailedOneReplacesIt) {
  open({"--scene", "bullets-wall"});
  dbg().command(Command::openRecording);
  frames(2);
  type(folder_);
  enter();
  // The control: the first path really failed, and said so.
  ASSERT_NE(dbg().message().find("is a directory, not a recording"), std::string::npos)
      << dbg().message();
  ASSERT_NE(dbg().session().primary().sim(), nullptr) << "the scene stays";

  dbg().command(Command::openRecording);
  frames(2);
  type(sampleRecording());  // an absolute path, taken as it is
  enter();
  EXPECT_EQ(dbg().message(), "") << "typed: " << sampleRecording();
  EXPECT_NE(dbg().session().primary().replay(), nullptr) << "the recording is open";
}

// The same in Ctrl+O's level path (clicked into, as a person does), and the error about the
// old path is gone once the path is being changed, not left on screen under the new one.
TEST_F(OpenDialogs, ALevelPathTypedAfterAFailedOneReplacesItAndClearsItsError) {
  open({"--scene", "bullets-wall"});
  dbg().openFile(folder_);
  ASSERT_NE(dbg().message().find("is a directory, not a file"), std::string::npos)
      << dbg().message();
  dbg().command(Command::openScene);
  frames(2);
  const std::string missing = folder_ + "/gone/level.tmj";
  // The path field, found as a person finds it: under the mouse.
  ImVec2 field = pathField();
  ASSERT_GT(field.x, 0.0f) << "no path field under the mouse";
  // First the failed path, so the field holds it...
  click(field);
  type(folder_);
  dbg().openFile("/");  // another error, to see that this Enter makes its own
  enter();
  ASSERT_NE(dbg().message().find(folder_ + ": is a directory, not a file"), std::string::npos)
      << dbg().message();
  // ...then a new one typed over it.
  dbg().command(Command::openScene);
  frames(2);
  field = pathField();
  ASSERT_GT(field.x, 0.0f) << "no path field under the mouse";
  click(field);
  type(missing.substr(0, 4));
  EXPECT_EQ(dbg().message(), "") << "the old error stays while the path is edited";
  type(missing.substr(4));
  enter();
  EXPECT_NE(dbg().message().find(missing), std::string::npos) << "'" << dbg().message() << "'";
  EXPECT_EQ(dbg().message().find(folder_ + folder_), std::string::npos)
      << "appended to the old path: " << dbg().message();
}

}  // namespace
}  // namespace tv::viewer
