// The Pareto plot's rasterizer: a small RGB canvas with anti-aliased discs and lines, and text
// blitted from Dear ImGui's built-in font atlas (ProggyClean, rendered at twice its design
// size so the pixel font stays crisp).
#include "plot.hpp"

#include <stdexcept>

#ifdef TV_BENCH_PLOT
#include <imgui.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>
#endif

namespace tv::bench {

#ifndef TV_BENCH_PLOT

bool canPlot() {
  return false;
}
void writeScatterPng(const ScatterPlot&, const std::filesystem::path&) {
  throw std::runtime_error("tv-bench was built without Dear ImGui and stb: no PNG plots");
}

#else

namespace {

struct Rgb {
  double r, g, b;
};

constexpr Rgb kInk{0.13, 0.13, 0.15}, kGrid{0.88, 0.88, 0.9}, kMinor{0.95, 0.95, 0.96},
    kGood{0.16, 0.38, 0.75}, kBad{0.85, 0.2, 0.16}, kFront{0.1, 0.6, 0.3}, kMuted{0.45, 0.45, 0.5};

struct Box {
  double x0, y0, x1, y1;
  [[nodiscard]] bool meets(const Box& o) const {
    return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
};

class Canvas {
 public:
  Canvas(int w, int h) : w_(w), h_(h), px_(static_cast<std::size_t>(w * h) * 3, 255) {
    ImFontConfig cfg;
    cfg.OversampleH = cfg.OversampleV = 1;  // one atlas texel per canvas pixel: a plain blit
    cfg.PixelSnapH = true;
    cfg.SizePixels = 26.0f;
    big_ = atlas_.AddFontDefault(&cfg);
    cfg.SizePixels = 13.0f;
    small_ = atlas_.AddFontDefault(&cfg);
    atlas_.GetTexDataAsAlpha8(&tex_, &texW_, &texH_);
  }

  void blend(int x, int y, Rgb c, double a) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_ || a <= 0) return;
    a = std::min(a, 1.0);
    std::uint8_t* p = &px_[static_cast<std::size_t>(y * w_ + x) * 3];
    const double rgb[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k) {
      const double v = p[k] * (1 - a) + rgb[k] * 255.0 * a;
      p[k] = static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
    }
  }

  void fillRect(double x0, double y0, double x1, double y1, Rgb c, double a = 1.0) {
    for (int y = static_cast<int>(std::floor(y0)); y < static_cast<int>(std::ceil(y1)); ++y)
      for (int x = static_cast<int>(std::floor(x0)); x < static_cast<int>(std::ceil(x1)); ++x)
        blend(x, y, c, a);
  }

  /// Disc (or ring of the given width when width > 0), anti-aliased by distance.
  void disc(double cx, double cy, double r, Rgb c, double ringWidth = 0) {
    for (int y = static_cast<int>(cy - r - 2); y <= static_cast<int>(cy + r + 2); ++y) {
      for (int x = static_cast<int>(cx - r - 2); x <= static_cast<int>(cx + r + 2); ++x) {
        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        double a = std::clamp(r + 0.5 - d, 0.0, 1.0);
        if (ringWidth > 0) a = std::min(a, std::clamp(d - (r - ringWidth) + 0.5, 0.0, 1.0));
        blend(x, y, c, a);
      }
    }
  }

  /// A line of the given width, anti-aliased by distance to the segment.
  void line(double x0, double y0, double x1, double y1, Rgb c, double width) {
    const double minX = std::min(x0, x1) - width, maxX = std::max(x0, x1) + width;
    const double minY = std::min(y0, y1) - width, maxY = std::max(y0, y1) + width;
    const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    for (int y = static_cast<int>(minY); y <= static_cast<int>(maxY); ++y) {
      for (int x = static_cast<int>(minX); x <= static_cast<int>(maxX); ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double t =
            len2 > 0 ? std::clamp(((px - x0) * dx + (py - y0) * dy) / len2, 0.0, 1.0) : 0;
        const double d = std::hypot(px - (x0 + t * dx), py - (y0 + t * dy));
        blend(x, y, c, std::clamp(width * 0.5 + 0.5 - d, 0.0, 1.0));
      }
    }
  }

  [[nodiscard]] double textWidth(const std::string& s, bool big) const {
    const ImFont* f = big ? big_ : small_;
    double w = 0;
    for (const char ch : s) {
      if (const ImFontGlyph* g = f->FindGlyph(static_cast<ImWchar>(static_cast<unsigned char>(ch))))
        w += static_cast<double>(g->AdvanceX);
    }
    return w;
  }
  [[nodiscard]] double textHeight(bool big) const {
    return static_cast<double>((big ? big_ : small_)->FontSize);
  }

  /// Text with its top-left at (x, y); `vertical` writes bottom to top, rotated a quarter turn.
  void text(double x, double y, const std::string& s, Rgb c, bool big, bool vertical = false) {
    const ImFont* f = big ? big_ : small_;
    double pen = 0;
    for (const char ch : s) {
      const ImFontGlyph* g = f->FindGlyph(static_cast<ImWchar>(static_cast<unsigned char>(ch)));
      if (!g) continue;
      const int u0 = static_cast<int>(std::lround(g->U0 * static_cast<float>(texW_)));
      const int v0 = static_cast<int>(std::lround(g->V0 * static_cast<float>(texH_)));
      const int gw = static_cast<int>(std::lround((g->U1 - g->U0) * static_cast<float>(texW_)));
      const int gh = static_cast<int>(std::lround((g->V1 - g->V0) * static_cast<float>(texH_)));
      for (int j = 0; j < gh; ++j) {
        for (int i = 0; i < gw; ++i) {
          const double a = tex_[(v0 + j) * texW_ + u0 + i] / 255.0;
          const double gx = pen + static_cast<double>(g->X0) + i;
          const double gy = static_cast<double>(g->Y0) + j;
          if (vertical) {
            blend(static_cast<int>(std::lround(x + gy)), static_cast<int>(std::lround(y - gx)), c,
                  a);
          } else {
            blend(static_cast<int>(std::lround(x + gx)), static_cast<int>(std::lround(y + gy)), c,
                  a);
          }
        }
      }
      pen += static_cast<double>(g->AdvanceX);
    }
  }

  void save(const std::filesystem::path& path) const {
    if (!stbi_write_png(path.string().c_str(), w_, h_, 3, px_.data(), w_ * 3)) {
      throw std::runtime_error("could not write '" + path.string() + "'");
    }
  }

 private:
  int w_, h_;
  std::vector<std::uint8_t> px_;
  ImFontAtlas atlas_;
  ImFont* big_ = nullptr;
  ImFont* small_ = nullptr;
  unsigned char* tex_ = nullptr;
  int texW_ = 0, texH_ = 0;
};

std::string decadeLabel(int e, bool time) {
  if (time) {
    static const char* const kUnits[] = {"ns", "us", "ms", "s"};
    const int u = std::clamp(e / 3, 0, 3);
    const double v = std::pow(10.0, e - 3 * u);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g %s", v, kUnits[u]);
    return buf;
  }
  if (e >= 0 && e <= 3) return std::to_string(static_cast<int>(std::pow(10.0, e)));
  return "1e" + std::to_string(e);
}

}  // namespace

bool canPlot() {
  return true;
}

void writeScatterPng(const ScatterPlot& plot, const std::filesystem::path& path) {
  constexpr int kW = 1400, kH = 900;
  Canvas c(kW, kH);
  const double left = 130, right = kW - 60, top = 110, bottom = kH - 150;
  const double zeroBand = 80;  // below the log axis: where error 0 is drawn
  const double plotBottom = bottom - zeroBand;

  double minX = 1e300, maxX = 0, minY = 1e300, maxY = 0;
  for (const PlotPoint& p : plot.points) {
    minX = std::min(minX, p.x);
    maxX = std::max(maxX, p.x);
    if (p.y > 0) {
      minY = std::min(minY, p.y);
      maxY = std::max(maxY, p.y);
    }
  }
  if (maxY == 0) minY = maxY = 1;
  const int ex0 = static_cast<int>(std::floor(std::log10(minX))),
            ex1 = static_cast<int>(std::ceil(std::log10(maxX * 1.05)));
  const int ey0 = static_cast<int>(std::floor(std::log10(minY))),
            ey1 = static_cast<int>(std::ceil(std::log10(maxY * 1.05)));
  const auto sx = [&](double x) {
    return left + (std::log10(x) - ex0) / std::max(ex1 - ex0, 1) * (right - left);
  };
  const auto sy = [&](double y) {
    if (y <= 0) return bottom - zeroBand * 0.4;
    return plotBottom - (std::log10(y) - ey0) / std::max(ey1 - ey0, 1) * (plotBottom - top);
  };

  // Grid and axes.
  for (int e = ex0; e <= ex1; ++e) {
    for (int m = 2; m <= 9 && e < ex1; ++m) {
      const double x = sx(m * std::pow(10.0, e));
      c.line(x, top, x, bottom, kMinor, 1);
    }
    const double x = sx(std::pow(10.0, e));
    c.line(x, top, x, bottom, kGrid, 1.5);
    const std::string l = decadeLabel(e, true);
    c.text(x - c.textWidth(l, true) / 2, bottom + 10, l, kInk, true);
  }
  for (int e = ey0; e <= ey1; ++e) {
    const double y = sy(std::pow(10.0, e));
    c.line(left, y, right, y, kGrid, 1.5);
    const std::string l = decadeLabel(e, false);
    c.text(left - 12 - c.textWidth(l, true), y - c.textHeight(true) / 2, l, kInk, true);
  }
  c.fillRect(left, plotBottom + 4, right, bottom, {0.96, 0.97, 0.94});
  c.text(left - 12 - c.textWidth("0", true), sy(0) - c.textHeight(true) / 2, "0", kInk, true);
  c.text(right - 8 - c.textWidth("error 0: exact", false), plotBottom + 8, "error 0: exact", kMuted,
         false);
  c.line(left, top, left, bottom, kInk, 2);
  c.line(left, bottom, right, bottom, kInk, 2);

  // Titles.
  c.text(left, 24, plot.title, kInk, true);
  c.text(left, 62, plot.subtitle, kMuted, true);
  c.text((left + right) / 2 - c.textWidth(plot.xLabel, true) / 2, bottom + 46, plot.xLabel, kInk,
         true);
  c.text(28, (top + bottom) / 2 + c.textWidth(plot.yLabel, true) / 2, plot.yLabel, kInk, true,
         true);

  // The front: a staircase through the front points in time order.
  std::vector<const PlotPoint*> front;
  for (const PlotPoint& p : plot.points)
    if (p.front) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const PlotPoint* a, const PlotPoint* b) { return a->x < b->x; });
  for (std::size_t i = 0; i + 1 < front.size(); ++i) {
    const double x0 = sx(front[i]->x), y0 = sy(front[i]->y);
    const double x1 = sx(front[i + 1]->x), y1 = sy(front[i + 1]->y);
    c.line(x0, y0, x1, y0, kFront, 3);
    c.line(x1, y0, x1, y1, kFront, 3);
  }

  // Points, then labels placed where they overlap neither a point nor another label.
  std::vector<Box> taken;
  for (const PlotPoint& p : plot.points) {
    const double x = sx(p.x), y = sy(p.y);
    taken.push_back({x - 8, y - 8, x + 8, y + 8});
  }
  for (const PlotPoint& p : plot.points) {
    const double x = sx(p.x), y = sy(p.y);
    if (p.front) c.disc(x, y, 11, kFront, 3);
    if (p.bad) {
      c.disc(x, y, 7, kBad, 3);
    } else {
      c.disc(x, y, 7, kGood);
    }
  }
  for (const PlotPoint& p : plot.points) {
    const double x = sx(p.x), y = sy(p.y);
    const double w = c.textWidth(p.label, true), h = c.textHeight(true);
    // Beside the point first, then further up or down the same side (with a leader line).
    std::vector<std::pair<double, double> > offsets;
    for (int k = 0; k <= 8; ++k) {
      for (const int sign : {-1, 1}) {
        const double dy = -h / 2 + sign * k * (h + 6);
        offsets.emplace_back(14, dy);
        offsets.emplace_back(-14 - w, dy);
        if (k == 0) break;
      }
      if (k == 0) {
        offsets.emplace_back(-w / 2, -h - 12);
        offsets.emplace_back(-w / 2, 12);
      }
    }
    Box chosen{x + 14, y - h / 2, x + 14 + w, y + h / 2};
    bool placed = false;
    for (const auto& [ox, oy] : offsets) {
      const Box b{x + ox - 3, y + oy - 2, x + ox + w + 3, y + oy + h + 2};
      if (b.x0 < left + 2 || b.x1 > right - 2 || b.y0 < top - 20 || b.y1 > bottom - 2) continue;
      if (std::none_of(taken.begin(), taken.end(), [&](const Box& t) { return t.meets(b); })) {
        chosen = b;
        placed = true;
        break;
      }
    }
    if (!placed) chosen = {x + 14 - 3, y - h / 2 - 2, x + 14 + w + 3, y + h / 2 + 2};
    taken.push_back(chosen);
    if (chosen.y1 < y - 10 || chosen.y0 > y + 10) {
      const double lx = chosen.x0 > x ? chosen.x0 : chosen.x1;
      const double ly = chosen.y1 < y ? chosen.y1 - 4 : chosen.y0 + 4;
      c.line(x, y, lx, ly, kMuted, 1);
    }
    c.fillRect(chosen.x0, chosen.y0, chosen.x1, chosen.y1, {1, 1, 1}, 0.85);
    c.text(chosen.x0 + 3, chosen.y0 + 2, p.label, p.bad ? kBad : kInk, true);
  }

  // Legend, under the x axis label.
  const double ly = kH - 40;
  double lx = left;
  c.disc(lx + 8, ly + 12, 7, kGood);
  c.text(lx + 24, ly, plot.legendGood, kInk, true);
  lx += 24 + c.textWidth(plot.legendGood, true) + 40;
  c.disc(lx + 8, ly + 12, 7, kBad, 3);
  c.text(lx + 24, ly, plot.legendBad, kInk, true);
  lx += 24 + c.textWidth(plot.legendBad, true) + 40;
  c.line(lx, ly + 12, lx + 40, ly + 12, kFront, 3);
  c.disc(lx + 20, ly + 12, 11, kFront, 3);
  c.text(lx + 52, ly, plot.legendFront, kInk, true);
  c.save(path);
}

#endif

}  // namespace tv::bench
