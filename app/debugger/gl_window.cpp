#include "gl_window.hpp"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>

#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"
#include "imgui.h"
#include "stb_image_write.h"

namespace tv::viewer {

namespace {

std::vector<KeyPress> gKeys;  // one window per process; GLFW callbacks carry no closure

// A key pressed and released between two frames (a quick tap, or xdotool) would never be seen
// down by ImGui 1.86, which polls io.KeysDown once a frame: Enter in the scene picker did
// nothing. Such a release is held back one frame.
std::vector<int> gPressed;        // pressed since the last frame began
std::vector<int> gTapped;         // pressed and released since then
std::vector<int> gReleaseNext;    // held down for one frame; released at the next

void onKey(GLFWwindow* /*window*/, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_RELEASE) gKeys.push_back({key, mods});
  if (key < 0 || key >= static_cast<int>(IM_ARRAYSIZE(ImGuiIO::KeysDown))) return;
  if (action == GLFW_PRESS) gPressed.push_back(key);
  if (action == GLFW_RELEASE && std::find(gPressed.begin(), gPressed.end(), key) != gPressed.end())
    gTapped.push_back(key);
}

std::vector<std::string> gDrops;  // files dropped on the window, in order

void onDrop(GLFWwindow* /*window*/, int count, const char** paths) {
  for (int i = 0; i < count; ++i) gDrops.emplace_back(paths[i]);
}

// Mesa's GLX loads its driver (swrast_dri.so for llvmpipe) with dlopen and unloads it when the
// display closes. A few allocations the driver keeps for the life of the process are then
// reported by LeakSanitizer against an unmapped address, which no suppression can name. Marking
// the driver never-unloaded keeps it mapped until exit (which follows at once), so the
// sanitizer builds' suppressions (tests/viewer/glx.lsan.supp) can name it. Nothing else changes.
int pinDriver(dl_phdr_info* info, std::size_t /*size*/, void* /*data*/) {
  if (info->dlpi_name && std::strstr(info->dlpi_name, "_dri.so")) {
    (void)dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  }
  return 0;
}

void onGlfwError(int code, const char* text) {
  std::fprintf(stderr, "tv-debugger: GLFW error 0x%x: %s\n", static_cast<unsigned>(code), text);
}

// The default 1280x720 (scaled to the monitor) is larger than a 1024x640 screen: shrink the
// window, its frame included, to the monitor's work area (the screen less the desktop's panels)
// and put it at the area's corner, so that no part of it is off screen.
void fitWorkArea(GLFWwindow* window) {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (monitor == nullptr) return;
  int ax = 0, ay = 0, aw = 0, ah = 0;
  glfwGetMonitorWorkarea(monitor, &ax, &ay, &aw, &ah);
  int left = 0, top = 0, right = 0, bottom = 0;
  glfwGetWindowFrameSize(window, &left, &top, &right, &bottom);
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  const int maxW = aw - left - right, maxH = ah - top - bottom;
  if (aw <= 0 || ah <= 0 || maxW <= 0 || maxH <= 0 || (w <= maxW && h <= maxH)) return;
  glfwSetWindowSize(window, std::min(w, maxW), std::min(h, maxH));
  glfwSetWindowPos(window, ax + left, ay + top);
}

}  // namespace

GlWindow::GlWindow(const WindowConfig& config) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    throw std::runtime_error(
        "cannot open a window (no display?). Without a display, tv-render draws the same "
        "pictures into PNG files");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, config.exact ? GLFW_FALSE : GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, config.exact ? GLFW_FALSE : GLFW_TRUE);
  window_ = glfwCreateWindow(config.width, config.height, config.title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window");
  }
  if (!config.exact) fitWorkArea(window_);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(config.exact ? 0 : 1);
  dl_iterate_phdr(pinDriver, nullptr);

  // Installed before the backend's, which then chains to it.
  glfwSetKeyCallback(window_, onKey);
  glfwSetDropCallback(window_, onDrop);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // Our own settings file holds what must survive a restart; ImGui's would make pictures
  // depend on the last session's window positions.
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  if (!ImGui_ImplGlfw_InitForOpenGL(window_, true) ||
      !ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw std::runtime_error("Dear ImGui's GLFW / OpenGL3 backends failed to initialise");
  }
}

GlWindow::~GlWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlWindow::shouldClose() const {
  return glfwWindowShouldClose(window_) != 0;
}

void GlWindow::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlWindow::beginFrame(bool idle) {
  ImGuiIO& io = ImGui::GetIO();
  for (const int k : gReleaseNext) io.KeysDown[k] = false;
  const bool releasing = !gReleaseNext.empty();
  gReleaseNext.clear();
  if (idle && !releasing) {
    glfwWaitEventsTimeout(0.1);
  } else {
    glfwPollEvents();
  }
  for (const int k : gTapped) io.KeysDown[k] = true;
  gReleaseNext.swap(gTapped);
  gTapped.clear();
  gPressed.clear();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
}

void GlWindow::render(std::uint32_t background) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glViewport(0, 0, w, h);
  const ImVec4 bg = ImGui::ColorConvertU32ToFloat4(background);
  glClearColor(bg.x, bg.y, bg.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GlWindow::swap() {
  glfwSwapBuffers(window_);
}

std::vector<std::uint8_t> GlWindow::readRgb(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<std::uint8_t> rgba(w * h * 4);
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // GL's rows run bottom-up; PNG's top-down. Alpha is dropped: the pictures are opaque.
  std::vector<std::uint8_t> rgb(w * h * 3);
  for (std::size_t y = 0; y < h; ++y) {
    const std::uint8_t* src = rgba.data() + (h - 1 - y) * w * 4;
    std::uint8_t* dst = rgb.data() + y * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      dst[x * 3] = src[x * 4];
      dst[x * 3 + 1] = src[x * 4 + 1];
      dst[x * 3 + 2] = src[x * 4 + 2];
    }
  }
  return rgb;
}

float GlWindow::contentScale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return x > 0.0f ? x : 1.0f;
}

std::vector<KeyPress> GlWindow::takeKeys() {
  std::vector<KeyPress> out;
  out.swap(gKeys);
  return out;
}

std::vector<std::string> GlWindow::takeDrops() {
  std::vector<std::string> out;
  out.swap(gDrops);
  return out;
}

void GlWindow::windowSize(int& width, int& height) const {
  glfwGetWindowSize(window_, &width, &height);
}

void writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
  if (!stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error("could not write '" + path + "'");
  }
}

}  // namespace tv::viewer
