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

  // The text's characters: UTF-8 up to two bytes (the font has Latin-1, e.g. the µ of µs).
  [[nodiscard]] static std::vector<ImWchar> chars(const std::string& s) {
    std::vector<ImWchar> out;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto b = static_cast<unsigned char>(s[i]);
      if (b >= 0xC0 && b < 0xE0 && i + 1 < s.size()) {
        const auto b2 = static_cast<unsigned char>(s[++i]);
        out.push_back(static_cast<ImWchar>(((b & 0x1Fu) << 6) | (b2 & 0x3Fu)));
      } else {
        out.push_back(static_cast<ImWchar>(b));
      }
    }
    return out;
  }

  [[nodiscard]] double textWidth(const std::string& s, bool big) const {
    const ImFont* f = big ? big_ : small_;
    double w = 0;
    for (const ImWchar ch : chars(s)) {
      if (const ImFontGlyph* g = f->FindGlyph(ch)) w += static_cast<double>(g->AdvanceX);
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
    for (const ImWchar ch : chars(s)) {
      const ImFontGlyph* g = f->FindGlyph(ch);
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
    static const char* const kUnits[] = {"ns", "\xC2\xB5s", "ms", "s"};
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
  const std::size_t n = plot.points.size();
  const std::size_t valueCols = plot.keyColumns.size();
  // The key beside the plot: marker, number, label, then the values, one row per point.
  std::vector<std::string> numbers(n);
  for (std::size_t i = 0; i < n; ++i) numbers[i] = std::to_string(i + 1);
  double numW = 0, labelW = 0;
  std::vector<double> valueW(valueCols, 0);
  {
    const Canvas measure(1, 1);
    numW = measure.textWidth("#", true);
    labelW = measure.textWidth("configuration", true);
    for (std::size_t k = 0; k < valueCols; ++k)
      valueW[k] = measure.textWidth(plot.keyColumns[k], true);
    for (std::size_t i = 0; i < n; ++i) {
      const PlotPoint& p = plot.points[i];
      numW = std::max(numW, measure.textWidth(numbers[i], true));
      labelW = std::max(labelW, measure.textWidth(p.label, true));
      for (std::size_t k = 0; k < valueCols && k < p.keyValues.size(); ++k)
        valueW[k] = std::max(valueW[k], measure.textWidth(p.keyValues[k], true));
    }
  }
  constexpr double kMarkerW = 34, kGap = 14, kValueGap = 28, kRowH = 32, kPlotW = 1000;
  double keyW = kMarkerW + numW + kGap + labelW;
  for (const double w : valueW) keyW += kValueGap + w;
  const double left = 130, right = left + kPlotW, top = 110;
  const double keyX = right + 60;
  const int kW = static_cast<int>(std::ceil(keyX + keyW + 30));
  const int kH = static_cast<int>(
      std::max(900.0, std::ceil(top + kRowH * static_cast<double>(n + 1) + 160)));
  Canvas c(kW, kH);
  const double bottom = kH - 150;
  const double zeroBand = 120;  // below the log axis: where error 0 is drawn, in three rows
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
    // Between the decades: a line at every multiple, and a label at 2 and 5 (3 more when the
    // axis spans at most two decades), so a point's error can be read off the axis.
    for (int m = 2; m <= 9 && e < ey1; ++m) {
      const double v = m * std::pow(10.0, e);
      const double ym = sy(v);
      c.line(left, ym, right, ym, kMinor, 1);
      const bool labelled = m == 2 || m == 5 || (ey1 - ey0 <= 2 && (m == 3 || m == 7));
      if (!labelled) continue;
      char text[32];
      std::snprintf(text, sizeof text, "%g", v);
      c.text(left - 12 - c.textWidth(text, true), ym - c.textHeight(true) / 2, text, kMuted, true);
    }
  }
  c.fillRect(left, plotBottom + 4, right, bottom, {0.96, 0.97, 0.94});
  c.text(left - 12 - c.textWidth("0", true), sy(0) - c.textHeight(true) / 2, "0", kInk, true);
  const std::string bandNote = "error 0: exact";
  const Box bandBox{right - 12 - c.textWidth(bandNote, false), plotBottom + 6, right - 4,
                    plotBottom + 10 + c.textHeight(false)};
  c.text(bandBox.x0 + 4, plotBottom + 8, bandNote, kMuted, false);
  c.line(left, top, left, bottom, kInk, 2);
  c.line(left, bottom, right, bottom, kInk, 2);

  // Titles.
  c.text(left, 24, plot.title, kInk, true);
  c.text(left, 62, plot.subtitle, kMuted, true);
  c.text((left + right) / 2 - c.textWidth(plot.xLabel, true) / 2, bottom + 46, plot.xLabel, kInk,
         true);
  c.text(28, (top + bottom) / 2 + c.textWidth(plot.yLabel, true) / 2, plot.yLabel, kInk, true,
         true);

  // Where each point is drawn. Exact points (error 0) share the band under the axis: they are
  // spread over three rows there, so points close in time (sweep, continuous, adaptive) each
  // keep a disc and a tag of their own.
  std::vector<double> px(n), py(n);
  for (std::size_t i = 0; i < n; ++i) {
    px[i] = sx(plot.points[i].x);
    py[i] = sy(plot.points[i].y);
  }
  {
    std::vector<std::size_t> zero;
    for (std::size_t i = 0; i < n; ++i)
      if (plot.points[i].y <= 0) zero.push_back(i);
    std::sort(zero.begin(), zero.end(), [&](std::size_t a, std::size_t b) { return px[a] < px[b]; });
    std::vector<std::vector<double>> rows(3);
    for (const std::size_t i : zero) {
      std::size_t r = 0;
      for (; r < rows.size(); ++r) {
        if (std::none_of(rows[r].begin(), rows[r].end(),
                         [&](double x) { return std::abs(x - px[i]) < 60.0; }))
          break;
      }
      if (r == rows.size()) r = 0;
      rows[r].push_back(px[i]);
      py[i] = plotBottom + 4 + (zeroBand - 4) * (0.2 + 0.3 * static_cast<double>(r));
    }
  }

  // The front: a staircase through the front points in time order.
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < n; ++i)
    if (plot.points[i].front) front.push_back(i);
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return px[a] < px[b]; });
  struct Seg {
    double x0, y0, x1, y1;
  };
  std::vector<Seg> frontSegs;
  for (std::size_t i = 0; i + 1 < front.size(); ++i) {
    const double x0 = px[front[i]], y0 = py[front[i]];
    const double x1 = px[front[i + 1]], y1 = py[front[i + 1]];
    frontSegs.push_back({x0, y0, x1, y0});
    frontSegs.push_back({x1, y0, x1, y1});
  }
  for (const Seg& sg : frontSegs) c.line(sg.x0, sg.y0, sg.x1, sg.y1, kFront, 3);

  // Points.
  for (std::size_t i = 0; i < n; ++i) {
    const PlotPoint& p = plot.points[i];
    if (p.front) c.disc(px[i], py[i], 11, kFront, 3);
    if (p.bad) {
      c.disc(px[i], py[i], 7, kBad, 3);
    } else {
      c.disc(px[i], py[i], 7, kGood);
    }
  }

  // Number tags. Points whose discs overlap share one tag ("14,15"). Each tag goes right next
  // to its point if it can, else a little further out with a leader line; a tag never leaves the
  // plot area, covers a point, another tag or a leader, and leaders never cross each other or
  // pass over a point. Crowded points are placed first, while there is still room near them.
  struct Tag {
    std::string text;
    std::vector<std::size_t> members;
    double x = 0, y = 0;  // the first member's centre
    bool bad = false;
  };
  std::vector<Tag> tags;
  for (std::size_t i = 0; i < n; ++i) {
    Tag* joined = nullptr;
    for (Tag& t : tags) {
      if (std::hypot(px[i] - t.x, py[i] - t.y) < 9) joined = &t;
    }
    if (joined) {
      joined->text += "," + numbers[i];
      joined->members.push_back(i);
      joined->bad = joined->bad || plot.points[i].bad;
    } else {
      tags.push_back({numbers[i], {i}, px[i], py[i], plot.points[i].bad});
    }
  }
  const auto crowd = [&](const Tag& t) {
    int k = 0;
    for (std::size_t j = 0; j < n; ++j) k += std::hypot(px[j] - t.x, py[j] - t.y) < 90 ? 1 : 0;
    return k;
  };
  std::vector<std::size_t> order(tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return crowd(tags[a]) > crowd(tags[b]); });

  const auto segsCross = [](const Seg& a, const Seg& b) {
    const auto cross = [](double ax, double ay, double bx, double by, double cx, double cy) {
      return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    };
    const double d1 = cross(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0);
    const double d2 = cross(a.x0, a.y0, a.x1, a.y1, b.x1, b.y1);
    const double d3 = cross(b.x0, b.y0, b.x1, b.y1, a.x0, a.y0);
    const double d4 = cross(b.x0, b.y0, b.x1, b.y1, a.x1, a.y1);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
  };
  const auto segDist = [](const Seg& sg, double x, double y) {
    const double dx = sg.x1 - sg.x0, dy = sg.y1 - sg.y0, len2 = dx * dx + dy * dy;
    const double t =
        len2 > 0 ? std::clamp(((x - sg.x0) * dx + (y - sg.y0) * dy) / len2, 0.0, 1.0) : 0;
    return std::hypot(x - (sg.x0 + t * dx), y - (sg.y0 + t * dy));
  };
  const auto segMeetsBox = [&](const Seg& sg, const Box& b) {
    const double len = std::hypot(sg.x1 - sg.x0, sg.y1 - sg.y0);
    const int steps = std::max(1, static_cast<int>(len / 2));
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const double x = sg.x0 + t * (sg.x1 - sg.x0), y = sg.y0 + t * (sg.y1 - sg.y0);
      if (x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1) return true;
    }
    return false;
  };

  std::vector<Box> placed;
  std::vector<Seg> leaders;
  const double th = c.textHeight(true);
  struct Drawn {
    Box box;
    bool leader;
    Seg seg;
    const Tag* tag;
  };
  std::vector<Drawn> drawn;
  for (const std::size_t ti : order) {
    const Tag& t = tags[ti];
    const double w = c.textWidth(t.text, true) + 8, h = th + 4;
    std::vector<std::size_t> own = t.members;
    const auto isOwn = [&](std::size_t j) {
      return std::find(own.begin(), own.end(), j) != own.end();
    };
    // Directions: right, left, up, down, then the diagonals; rings further and further out.
    static const double kDirs[][2] = {{1, 0},   {-1, 0},    {0, -1},   {0, 1},
                                      {1, -1},  {-1, -1},   {1, 1},    {-1, 1},
                                      {1, -0.5}, {-1, -0.5}, {1, 0.5}, {-1, 0.5}};
    bool done = false;
    Drawn best{{t.x + 13, t.y - h / 2, t.x + 13 + w, t.y + h / 2}, false, {}, &t};
    for (int pass = 0; pass < 2 && !done; ++pass) {
      for (const double d : {13.0, 26.0, 42.0, 62.0, 86.0, 115.0, 150.0, 190.0}) {
        for (const auto& dir : kDirs) {
          const double len = std::hypot(dir[0], dir[1]);
          const double ux = dir[0] / len, uy = dir[1] / len;
          const double cx = t.x + ux * d + (dir[0] > 0 ? w / 2 : dir[0] < 0 ? -w / 2 : 0);
          const double cy = t.y + uy * d + (dir[1] > 0 ? h / 2 : dir[1] < 0 ? -h / 2 : 0);
          const Box b{cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2};
          if (b.x0 < left + 4 || b.x1 > right - 4 || b.y0 < top + 2 || b.y1 > bottom - 2) continue;
          if (b.meets(bandBox)) continue;
          const Box margin{b.x0 - 3, b.y0 - 3, b.x1 + 3, b.y1 + 3};
          bool ok = std::none_of(placed.begin(), placed.end(),
                                 [&](const Box& o) { return o.meets(margin); });
          for (std::size_t j = 0; ok && j < n; ++j) {
            const double r = isOwn(j) ? 11 : 14;
            if (Box{px[j] - r, py[j] - r, px[j] + r, py[j] + r}.meets(b)) ok = false;
          }
          for (std::size_t k = 0; ok && k < leaders.size(); ++k)
            if (segMeetsBox(leaders[k], margin)) ok = false;
          if (ok && pass == 0) {
            for (const Seg& sg : frontSegs)
              if (segMeetsBox(sg, margin)) ok = false;
          }
          Seg leader{};
          const bool needsLeader = d > 13.0;
          if (ok && needsLeader) {
            // From the disc's edge to the nearest point of the tag.
            const double nx = std::clamp(t.x, b.x0, b.x1), ny = std::clamp(t.y, b.y0, b.y1);
            const double dl = std::hypot(nx - t.x, ny - t.y);
            leader = {t.x + (nx - t.x) / dl * 9, t.y + (ny - t.y) / dl * 9, nx, ny};
            for (const Seg& o : leaders)
              if (segsCross(o, leader)) ok = false;
            for (std::size_t j = 0; ok && j < n; ++j)
              if (!isOwn(j) && segDist(leader, px[j], py[j]) < 13) ok = false;
            for (std::size_t k = 0; ok && k < placed.size(); ++k)
              if (segMeetsBox(leader, placed[k])) ok = false;
          }
          if (!ok) continue;
          best = {b, needsLeader, leader, &t};
          done = true;
          break;
        }
        if (done) break;
      }
    }
    placed.push_back(best.box);
    if (best.leader) leaders.push_back(best.seg);
    drawn.push_back(best);
  }
  for (const Drawn& dr : drawn) {
    if (dr.leader) c.line(dr.seg.x0, dr.seg.y0, dr.seg.x1, dr.seg.y1, kMuted, 1.5);
  }
  for (const Drawn& dr : drawn) {
    const Rgb col = dr.tag->bad ? kBad : kGood;
    c.fillRect(dr.box.x0, dr.box.y0, dr.box.x1, dr.box.y1, {1, 1, 1}, 0.92);
    c.line(dr.box.x0, dr.box.y0, dr.box.x1, dr.box.y0, col, 1);
    c.line(dr.box.x1, dr.box.y0, dr.box.x1, dr.box.y1, col, 1);
    c.line(dr.box.x1, dr.box.y1, dr.box.x0, dr.box.y1, col, 1);
    c.line(dr.box.x0, dr.box.y1, dr.box.x0, dr.box.y0, col, 1);
    c.text(dr.box.x0 + 4, dr.box.y0 + 2, dr.tag->text, col, true);
  }

  // The key, beside the plot.
  {
    double y = top - 6;
    const double numX = keyX + kMarkerW, labelX = numX + numW + kGap;
    std::vector<double> valueRight(valueCols);
    double x = labelX + labelW;
    for (std::size_t k = 0; k < valueCols; ++k) valueRight[k] = x += kValueGap + valueW[k];
    c.text(numX + numW - c.textWidth("#", true), y, "#", kMuted, true);
    c.text(labelX, y, "configuration", kMuted, true);
    for (std::size_t k = 0; k < valueCols; ++k)
      c.text(valueRight[k] - valueW[k] + (valueW[k] - c.textWidth(plot.keyColumns[k], true)), y,
             plot.keyColumns[k], kMuted, true);
    y += kRowH;
    c.line(keyX, y - 5, valueCols ? valueRight.back() : labelX + labelW, y - 5, kGrid, 1.5);
    for (std::size_t i = 0; i < n; ++i) {
      const PlotPoint& p = plot.points[i];
      if (i % 2 == 1)
        c.fillRect(keyX, y - 3, valueCols ? valueRight.back() + 6 : labelX + labelW, y + kRowH - 5,
                   {0.965, 0.965, 0.975});
      const double my = y + th / 2 - 1, mx = keyX + 14;
      if (p.front) c.disc(mx, my, 11, kFront, 3);
      if (p.bad) {
        c.disc(mx, my, 7, kBad, 3);
      } else {
        c.disc(mx, my, 7, kGood);
      }
      const Rgb col = p.bad ? kBad : kGood;
      c.text(numX + numW - c.textWidth(numbers[i], true), y, numbers[i], col, true);
      c.text(labelX, y, p.label, p.bad ? kBad : kInk, true);
      for (std::size_t k = 0; k < valueCols && k < p.keyValues.size(); ++k)
        c.text(valueRight[k] - c.textWidth(p.keyValues[k], true), y, p.keyValues[k], kInk, true);
      y += kRowH;
    }
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
