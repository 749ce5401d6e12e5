#include "bench/tradeoff.h"

#include "core/error.h"
#include "core/image.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace radview {

void markParetoFront(std::vector<TradeoffRow>& rows) {
  for (TradeoffRow& row : rows) {
    row.pareto = std::none_of(rows.begin(), rows.end(), [&](const TradeoffRow& other) {
      return other.frameMs <= row.frameMs && other.displayRmse <= row.displayRmse &&
             (other.frameMs < row.frameMs || other.displayRmse < row.displayRmse);
    });
  }
}

namespace {

std::string number(double v, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace

std::string markdownTable(const std::vector<TradeoffRow>& rows) {
  std::ostringstream out;
  out << "| method | setting | frame ms | triangles | RMSE | max | display RMSE (steps) | display max (steps) "
         "| Mach bands (steps/px) | C0 kinks (steps/px) |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TradeoffRow& r : rows) {
    const std::string b = r.pareto ? "**" : "";
    out << "| " << b << r.method << b << " | " << b << r.setting << b << " | " << number(r.frameMs) << " | "
        << r.triangles << " | " << number(r.rmse) << " | " << number(r.maxError) << " | " << b << number(r.displayRmse)
        << b << " | " << number(r.displayMax) << " | " << number(r.machBands) << " | " << number(r.c0Kinks) << " |\n";
  }
  return out.str();
}

std::string csvTable(const std::vector<TradeoffRow>& rows) {
  std::ostringstream out;
  out << "method,setting,frame_ms,triangles,rmse,max,display_rmse_steps,display_max_steps,mach_steps_per_px,"
         "c0_kink_steps_per_px,pareto\n";
  for (const TradeoffRow& r : rows)
    out << r.method << "," << r.setting << "," << number(r.frameMs, 6) << "," << r.triangles << "," << number(r.rmse, 6)
        << "," << number(r.maxError, 6) << "," << number(r.displayRmse, 6) << "," << number(r.displayMax, 6) << ","
        << number(r.machBands, 6) << "," << number(r.c0Kinks, 6) << "," << (r.pareto ? 1 : 0) << "\n";
  return out.str();
}

bool writeTradeoffPlot(const std::vector<TradeoffRow>& rows, const std::string& title, const std::string& path) {
  namespace IBA = OIIO::ImageBufAlgo;
  const int W = 960, H = 660, left = 90, right = 30, top = 70, bottom = 70;
  OIIO::ImageBuf plot(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::UINT8));
  const float white[3] = {1, 1, 1}, grey[3] = {0.85f, 0.85f, 0.85f}, black[3] = {0, 0, 0},
              blue[3] = {0.15f, 0.35f, 0.8f}, red[3] = {0.85f, 0.15f, 0.1f};
  IBA::fill(plot, white);

  double tMin = INFINITY, tMax = 0.0, eMin = INFINITY, eMax = 0.0;
  for (const TradeoffRow& r : rows) {
    if (!(r.frameMs > 0.0)) continue;
    tMin = std::min(tMin, r.frameMs);
    tMax = std::max(tMax, r.frameMs);
    eMin = std::min(eMin, r.displayRmse);
    eMax = std::max(eMax, r.displayRmse);
  }
  if (!(eMax > 0.0)) eMin = 0.0, eMax = 1.0;
  if (!(tMax > 0.0)) tMin = 1.0, tMax = 10.0;
  // Whole decades on the time axis, a round top on the error axis.
  const double d0 = std::floor(std::log10(tMin)), d1 = std::max(d0 + 1.0, std::ceil(std::log10(tMax)));
  // The error axis spans the rows' range, widened to steps of a round size (1, 2 or 5 x 10^k).
  const double span = std::max(eMax - eMin, 1e-3 * std::max(eMax, 1e-9));
  const double magnitude = std::pow(10.0, std::floor(std::log10(span / 5.0)));
  const double step = magnitude * (span / 5.0 > 5.0 * magnitude ? 10.0 : span / 5.0 > 2.0 * magnitude ? 5.0 : 2.0);
  const double eBottom = std::max(0.0, std::floor(eMin / step - 0.5) * step);
  const double eTop = std::ceil(eMax / step + 0.5) * step;
  auto px = [&](double ms) { return left + int((std::log10(ms) - d0) / (d1 - d0) * (W - left - right)); };
  auto py = [&](double e) { return H - bottom - int((e - eBottom) / (eTop - eBottom) * (H - top - bottom)); };

  const std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  const bool labels = std::filesystem::exists(font);
  auto text = [&](int x, int y, const std::string& s, int size, const float* colour,
                  IBA::TextAlignX ax = IBA::TextAlignX::Left) {
    if (labels) IBA::render_text(plot, x, y, s, size, font, OIIO::cspan<float>(colour, 3), ax);
  };
  for (double d = d0; d <= d1; ++d) {
    for (int k = 1; k < 10 && d + std::log10(k) <= d1; ++k)
      IBA::render_line(plot, px(std::pow(10.0, d) * k), top, px(std::pow(10.0, d) * k), H - bottom,
                       OIIO::cspan<float>(grey, 3));
    text(px(std::pow(10.0, d)), H - bottom + 22, number(std::pow(10.0, d)), 15, black, IBA::TextAlignX::Center);
  }
  for (double e = eBottom; e <= eTop + 0.5 * step; e += step) {
    IBA::render_line(plot, left, py(e), W - right, py(e), OIIO::cspan<float>(grey, 3));
    text(left - 8, py(e) + 5, number(e), 15, black, IBA::TextAlignX::Right);
  }
  IBA::render_box(plot, left, top, W - right, H - bottom, OIIO::cspan<float>(black, 3));
  text(W / 2, H - 20, "GPU frame time, ms (log scale)", 17, black, IBA::TextAlignX::Center);
  text(12, top - 12, "RMSE of displayed luminance against the final gather, 8-bit steps", 17, black);
  text(W / 2, 26, title, 18, black, IBA::TextAlignX::Center);

  std::vector<const TradeoffRow*> front;
  for (const TradeoffRow& r : rows) {
    if (!(r.frameMs > 0.0)) continue;
    const int x = px(r.frameMs), y = py(r.displayRmse);
    IBA::render_box(plot, x - 3, y - 3, x + 3, y + 3, OIIO::cspan<float>(r.pareto ? red : blue, 3), true);
    if (r.pareto) front.push_back(&r);
  }
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->frameMs < b->frameMs; });
  for (size_t i = 0; i + 1 < front.size(); ++i)
    IBA::render_line(plot, px(front[i]->frameMs), py(front[i]->displayRmse), px(front[i + 1]->frameMs),
                     py(front[i + 1]->displayRmse), OIIO::cspan<float>(red, 3));
  // Labels stagger upwards, so neighbours on the front do not overwrite each other.
  for (size_t i = 0; i < front.size(); ++i)
    text(px(front[i]->frameMs) + 7, py(front[i]->displayRmse) - 6 - 15 * int(i % 4),
         front[i]->method + " " + front[i]->setting, 13, red);

  Image rgba{W, H, std::vector<uint8_t>(size_t(W) * H * 4, 255)};
  std::vector<uint8_t> rgb(size_t(W) * H * 3);
  plot.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
  for (size_t i = 0; i < size_t(W) * H; ++i)
    for (int c = 0; c < 3; ++c) rgba.rgba[4 * i + c] = rgb[3 * i + c];
  writePng(rgba, path);
  return labels;
}

}  // namespace radview
