// The Pareto front and the reports of radview bench (renderer/bench/tradeoff.h).
#include "bench/tradeoff.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

TradeoffRow row(const char* method, double ms, double error) {
  TradeoffRow r;
  r.method = method;
  r.setting = "per pixel";
  r.frameMs = ms;
  r.displayError.meanSquare = error * error;  // exact: no interval
  return r;
}

// A row whose display error has a 95 % interval of about +-halfWidth (in RMS, for small widths).
TradeoffRow uncertain(const char* method, double error, double halfWidth) {
  TradeoffRow r = row(method, 1.0, error);
  r.displayError.standardError = 2.0 * error * halfWidth / 1.959963984540054;
  r.displayError.dof = 1e9;
  return r;
}

TEST(TradeoffTest, ParetoFrontKeepsRowsNoOtherBeatsOnBothAxes) {
  std::vector<TradeoffRow> rows = {row("fast", 1, 9),   row("slow-good", 10, 1),   row("dominated", 5, 9.5),
                                   row("middle", 3, 4), row("tie-slower", 3.5, 4), row("same", 3, 4)};
  markParetoFront(rows);
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_TRUE(rows[1].pareto);
  EXPECT_FALSE(rows[2].pareto);  // slower and worse than "fast"
  EXPECT_TRUE(rows[3].pareto);   // an exact twin does not dominate it
  EXPECT_FALSE(rows[4].pareto);  // as good as "middle", slower
  EXPECT_TRUE(rows[5].pareto);
}

TEST(TradeoffTest, TablesHaveOneLinePerRowAndMarkTheFront) {
  std::vector<TradeoffRow> rows = {row("a", 1, 2), row("b", 2, 3)};
  markParetoFront(rows);
  const std::string md = markdownTable(rows), csv = csvTable(rows);
  EXPECT_NE(md.find("| **a** |"), std::string::npos);
  EXPECT_NE(md.find("| b |"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find("\nb,per pixel,2,0,"), std::string::npos);
}

TEST(TradeoffTest, CsvKeepsItsColumnsAndAddsTheEstimatesByName) {
  const std::string csv = csvTable({row("a", 1, 2)});
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header.rfind("method,setting,frame_ms,triangles,rmse,max,display_rmse_steps,display_max_steps,"
                         "mach_steps_per_px,c0_kink_steps_per_px,pareto,",
                         0),
            0u);
  for (const char* column :
       {"rmse_estimate", "rmse_ci_low", "rmse_ci_high", "error_estimate_steps", "error_ci_low_steps",
        "error_ci_high_steps", "reference_noise_rmse", "reference_noise_steps", "image"})
    EXPECT_NE(("," + header + ",").find("," + std::string(column) + ","), std::string::npos) << column;
  // Every line has as many fields as the header.
  const std::string line = csv.substr(header.size() + 1);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(line.begin(), line.end(), ','));
}

// A setting with a comma is one quoted field (RFC 4180): Python's csv module reads it back.
TEST(TradeoffTest, CsvQuotesTextWithCommasOrQuotes) {
  TradeoffRow r = row("c1-quadratic", 1, 1);
  r.setting = "per pixel, C0 not relaxed";
  r.image = "say \"x\".exr";
  const std::string csv = csvTable({r});
  const std::string line = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(line.rfind("c1-quadratic,\"per pixel, C0 not relaxed\",1,", 0), 0u) << line;
  EXPECT_NE(line.find(",\"say \"\"x\"\".exr\","), std::string::npos) << line;
}

TEST(TradeoffTest, RowFilesAreNamedByMethodAndSetting) {
  TradeoffRow r = row("c1-quadratic", 1, 1);
  r.setting = "per pixel, C0 not relaxed";
  EXPECT_EQ(rowFileStem(r), "c1-quadratic-per-pixel-c0-not-relaxed");
  r.setting = "adaptive 0.5";
  EXPECT_EQ(rowFileStem(r), "c1-quadratic-adaptive-0.5");
}

TEST(TradeoffTest, PerPixelRowsWhoseIntervalsOverlapAreTies) {
  const std::vector<TradeoffRow> rows = {uncertain("gouraud", 2.0, 0.05), uncertain("bilinear", 2.08, 0.05),
                                         uncertain("clough-tocher", 1.5, 0.05)};
  const std::string report = tieReport(rows);
  EXPECT_NE(report.find("- clough-tocher 1.5 [1.449, 1.549] steps: ties with none; better than gouraud, bilinear"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("- gouraud 2 [1.949, 2.049] steps: ties with bilinear\n"), std::string::npos) << report;
}

}  // namespace
}  // namespace radview
