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
  r.displayRmse = error;
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

}  // namespace
}  // namespace radview
