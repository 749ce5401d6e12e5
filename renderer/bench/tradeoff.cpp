#include "bench/tradeoff.h"

#include "core/error.h"
#include "core/image.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace radview {

void markParetoFront(std::vector<TradeoffRow>& rows) {
  for (TradeoffRow& row : rows) {
    const double error = row.displayError.rms();
    row.pareto = std::none_of(rows.begin(), rows.end(), [&](const TradeoffRow& other) {
      const double otherError = other.displayError.rms();
      return other.frameMs <= row.frameMs && otherError <= error && (other.frameMs < row.frameMs || otherError < error);
    });
  }
}

std::string number(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

std::string withInterval(const ErrorEstimate& e) {
  if (e.standardError == 0.0) return number(e.rms());
  // Enough digits that the interval's width shows to two of them.
  const double width = e.rmsHigh() - e.rmsLow(), magnitude = std::max(e.rmsHigh(), 1e-300);
  const int digits = width > 0.0 ? std::clamp(int(std::ceil(std::log10(magnitude / width))) + 2, 3, 8) : 3;
  return number(e.rms(), digits) + " [" + number(e.rmsLow(), digits) + ", " + number(e.rmsHigh(), digits) + "]";
}

std::string rowFileStem(const TradeoffRow& row) {
  std::string stem = row.method + "-" + row.setting;
  std::string out;
  for (char c : stem) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.';
    if (keep)
      out += char(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

std::string markdownTable(const std::vector<TradeoffRow>& rows) {
  std::ostringstream out;
  out << "| method | setting | frame ms | triangles | error, steps [95 %] | error, linear [95 %] | max, steps "
         "| Mach bands (steps/px) | Mach error [95 %] | C0 kinks (steps/px) | C0 kink error [95 %] |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TradeoffRow& r : rows) {
    const std::string b = r.pareto ? "**" : "";
    out << "| " << b << r.method << b << " | " << b << r.setting << b << " | " << number(r.frameMs) << " | "
        << r.triangles << " | " << b << withInterval(r.displayError) << b << " | " << withInterval(r.linearError)
        << " | " << number(r.displayMax) << " | " << number(r.machBands) << " | " << withInterval(r.machError) << " | "
        << number(r.c0Kinks) << " | " << withInterval(r.c0KinkError) << " |\n";
  }
  return out.str();
}

namespace {

// A text field as RFC 4180 has it: quoted where it holds a comma, a quote or a line break (a
// setting such as "per pixel, C0 not relaxed"), its quotes doubled.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::string csvTable(const std::vector<TradeoffRow>& rows) {
  std::ostringstream out;
  out << "method,setting,frame_ms,triangles,rmse,max,display_rmse_steps,display_max_steps,mach_steps_per_px,"
         "c0_kink_steps_per_px,pareto,rmse_estimate,rmse_ci_low,rmse_ci_high,error_estimate_steps,error_ci_low_steps,"
         "error_ci_high_steps,reference_noise_rmse,reference_noise_steps,image,mach_error_steps_per_px,"
         "mach_error_ci_low,mach_error_ci_high,c0_kink_error_steps_per_px,c0_kink_error_ci_low,c0_kink_error_ci_high,"
         "solution_error_steps,solution_ci_low_steps,solution_ci_high_steps,reconstruction_error_steps,"
         "reconstruction_ci_low_steps,reconstruction_ci_high_steps\n";
  auto estimate = [&](const ErrorEstimate& e) {
    return number(e.rms(), 6) + "," + number(e.rmsLow(), 6) + "," + number(e.rmsHigh(), 6);
  };
  for (const TradeoffRow& r : rows)
    out << csvField(r.method) << "," << csvField(r.setting) << "," << number(r.frameMs, 6) << "," << r.triangles << ","
        << number(r.rmse, 6) << "," << number(r.maxError, 6) << "," << number(r.displayRmse, 6) << ","
        << number(r.displayMax, 6) << "," << number(r.machBands, 6) << "," << number(r.c0Kinks, 6) << ","
        << (r.pareto ? 1 : 0) << "," << estimate(r.linearError) << "," << estimate(r.displayError) << ","
        << number(r.referenceNoiseRmse, 6) << "," << number(r.referenceNoiseSteps, 6) << "," << csvField(r.image) << ","
        << estimate(r.machError) << "," << estimate(r.c0KinkError) << "," << (r.split ? estimate(r.solutionPart) : ",,")
        << "," << (r.split ? estimate(r.reconstructionPart) : ",,") << "\n";
  return out.str();
}

namespace {

// tieReport over the estimate `of` picks from each per-pixel row.
template <class Of>
std::string ties(const std::vector<TradeoffRow>& rows, Of of) {
  std::vector<const TradeoffRow*> perPixel;
  for (const TradeoffRow& r : rows)
    if (r.setting.rfind("per pixel", 0) == 0) perPixel.push_back(&r);
  std::sort(perPixel.begin(), perPixel.end(), [&](auto* a, auto* b) { return of(*a).rms() < of(*b).rms(); });
  auto name = [](const TradeoffRow* r) {
    return r->setting == "per pixel" ? r->method : r->method + " (" + r->setting.substr(11) + ")";
  };
  std::ostringstream out;
  for (const TradeoffRow* r : perPixel) {
    std::vector<std::string> ties, better;
    for (const TradeoffRow* other : perPixel) {
      if (other == r) continue;
      if (tie(of(*r), of(*other)))
        ties.push_back(name(other));
      else if (of(*r).rms() < of(*other).rms())
        better.push_back(name(other));
    }
    out << "- " << name(r) << " " << withInterval(of(*r)) << " steps: ";
    auto list = [&](const std::vector<std::string>& names) {
      std::string s;
      for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
      return s;
    };
    out << (ties.empty() ? "ties with none" : "ties with " + list(ties));
    if (!better.empty()) out << "; better than " << list(better);
    out << "\n";
  }
  return out.str();
}

}  // namespace

std::string tieReport(const std::vector<TradeoffRow>& rows) {
  return ties(rows, [](const TradeoffRow& r) -> const ErrorEstimate& { return r.displayError; });
}

std::string splitReport(const std::vector<TradeoffRow>& rows) {
  std::vector<TradeoffRow> split;
  for (const TradeoffRow& r : rows)
    if (r.split) split.push_back(r);
  if (split.empty()) return "";
  std::ostringstream out;
  out << "| method | setting | error, steps [95 %] | the solution's part | the reconstruction's part | nodes' noise |\n"
         "|---|---|---|---|---|---|\n";
  for (const TradeoffRow& r : split)
    out << "| " << r.method << " | " << r.setting << " | " << withInterval(r.displayError) << " | "
        << withInterval(r.solutionPart) << " | " << withInterval(r.reconstructionPart) << " | "
        << number(r.nodeNoiseSteps) << " |\n";
  out << "\nThe reconstruction's part, by error, with ties:\n\n"
      << ties(split, [](const TradeoffRow& r) -> const ErrorEstimate& { return r.reconstructionPart; });
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
  const TradeoffRow* best = nullptr;
  for (const TradeoffRow& r : rows) {
    if (!(r.frameMs > 0.0)) continue;
    tMin = std::min(tMin, r.frameMs);
    tMax = std::max(tMax, r.frameMs);
    eMin = std::min(eMin, r.displayError.rmsLow());
    eMax = std::max(eMax, r.displayError.rmsHigh());
    if (!best || r.displayError.rms() < best->displayError.rms()) best = &r;
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
  // The best row's interval: a bar that reaches into this band ties with it.
  const float band[3] = {0.99f, 0.93f, 0.8f};
  if (best && best->displayError.rmsHigh() > best->displayError.rmsLow())
    IBA::fill(plot, OIIO::cspan<float>(band, 3),
              OIIO::ROI(left, W - right, py(best->displayError.rmsHigh()), py(best->displayError.rmsLow()) + 1));
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
  text(12, top - 12, "Error of displayed luminance, 8-bit steps (bars: 95 % intervals; band: the best row's)", 17,
       black);
  text(W / 2, 26, title, 18, black, IBA::TextAlignX::Center);

  std::vector<const TradeoffRow*> front;
  for (const TradeoffRow& r : rows) {
    if (!(r.frameMs > 0.0)) continue;
    const int x = px(r.frameMs), y = py(r.displayError.rms());
    const float* colour = r.pareto ? red : blue;
    const int low = py(r.displayError.rmsLow()), high = py(r.displayError.rmsHigh());
    if (low - high >= 2) {
      IBA::render_line(plot, x, high, x, low, OIIO::cspan<float>(colour, 3));
      IBA::render_line(plot, x - 4, high, x + 4, high, OIIO::cspan<float>(colour, 3));
      IBA::render_line(plot, x - 4, low, x + 4, low, OIIO::cspan<float>(colour, 3));
    }
    IBA::render_box(plot, x - 3, y - 3, x + 3, y + 3, OIIO::cspan<float>(colour, 3), true);
    if (r.pareto) front.push_back(&r);
  }
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->frameMs < b->frameMs; });
  for (size_t i = 0; i + 1 < front.size(); ++i)
    IBA::render_line(plot, px(front[i]->frameMs), py(front[i]->displayError.rms()), px(front[i + 1]->frameMs),
                     py(front[i + 1]->displayError.rms()), OIIO::cspan<float>(red, 3));
  // Labels stagger upwards, so neighbours on the front do not overwrite each other.
  for (size_t i = 0; i < front.size(); ++i)
    text(px(front[i]->frameMs) + 7, py(front[i]->displayError.rms()) - 6 - 15 * int(i % 4),
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
