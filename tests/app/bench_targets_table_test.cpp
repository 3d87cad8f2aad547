// The table bench targets writes (apps/shadelgraph/bench_targets_table.cpp):
// figures in, each judged against its row's target, JSON and Markdown out.
// No device.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bench_targets_table.hpp"

namespace {

using sg::app::TargetCompare;
using sg::app::TargetFigure;
using sg::app::TargetRow;

TargetRow atMost(double target) {
  return {.id = "ratio", .figure = "a ÷ b", .scenes = "s", .unit = "ratio", .target = target};
}

TEST(BenchTargetsTable, FiguresAreJudgedAgainstTheTargetInItsDirection) {
  const TargetRow low = atMost(0.5);
  EXPECT_EQ(sg::app::figureMet(low, {.value = 0.5}), true);  // the bound itself meets it
  EXPECT_EQ(sg::app::figureMet(low, {.value = 0.51}), false);
  EXPECT_EQ(sg::app::figureMet(low, {.note = "skipped"}), std::nullopt);
  const TargetRow high{.id = "psnr", .unit = "dB", .compare = TargetCompare::AtLeast, .target = 40.0};
  EXPECT_EQ(sg::app::figureMet(high, {.value = 40.0}), true);
  EXPECT_EQ(sg::app::figureMet(high, {.value = 34.0}), false);
}

TEST(BenchTargetsTable, ARelativeTargetNeedsABefore) {
  const TargetRow row{.id = "geometry", .unit = "ms", .target = 0.5, .relativeToBefore = true};
  EXPECT_EQ(sg::app::figureMet(row, {.value = 240.0}), std::nullopt);
  EXPECT_EQ(sg::app::figureMet(row, {.value = 240.0, .before = 494.0}), true);
  EXPECT_EQ(sg::app::figureMet(row, {.value = 260.0, .before = 494.0}), false);
}

TEST(BenchTargetsTable, ARowIsMetOnlyWhenEveryFigureIs) {
  TargetRow row = atMost(1.0);
  EXPECT_EQ(sg::app::rowMet(row), std::nullopt);  // nothing measured
  row.figures = {{.scene = "a", .value = 0.5}, {.scene = "b", .note = "skipped"}};
  EXPECT_EQ(sg::app::rowMet(row), std::nullopt);  // one not judged, none failed
  row.figures.push_back({.scene = "c", .value = 2.0});
  EXPECT_EQ(sg::app::rowMet(row), false);
  row.figures = {{.scene = "a", .value = 0.5}, {.scene = "b", .value = 1.0}};
  EXPECT_EQ(sg::app::rowMet(row), true);
}

TEST(BenchTargetsTable, JsonHasEveryRowAndFigureWorstFirstWithTheBaselineApplied) {
  TargetRow psnr{.id = "psnr", .figure = "PSNR", .scenes = "models", .unit = "dB", .compare = TargetCompare::AtLeast,
                 .target = 40.0, .worstFirst = true};
  psnr.figures = {{.scene = "Duck", .size = "64x36", .value = 45.0},
                  {.scene = "Suzanne", .size = "64x36", .value = 34.0},
                  {.scene = "Box", .size = "64x36", .note = "skipped: not found"}};
  TargetRow geometry{.id = "geometry", .figure = "forward frame", .scenes = "heavy", .unit = "ms", .target = 0.5,
                     .relativeToBefore = true};
  geometry.figures = {{.scene = "Engine", .size = "64x36", .detail = "forward", .value = 60.0}};
  std::vector<TargetRow> rows{psnr, geometry};

  const nlohmann::json baseline{
      {"rows",
       {{{"id", "geometry"}, {"figures", {{{"scene", "Engine"}, {"size", "64x36"}, {"detail", "forward"}, {"value", 150.0}}}}},
        {{"id", "psnr"}, {"figures", {{{"scene", "Suzanne"}, {"size", "1280x720"}, {"detail", ""}, {"value", 30.0}}}}}}}};
  sg::app::applyBaseline(rows, baseline);
  EXPECT_EQ(rows[1].figures[0].before, 150.0);
  EXPECT_EQ(rows[0].figures[1].before, std::nullopt);  // another size: not the same figure

  const auto json = sg::app::targetsJson(rows, {{"repetitions", 1}});
  EXPECT_EQ(json["repetitions"], 1);
  ASSERT_EQ(json["rows"].size(), 2u);
  const auto& p = json["rows"][0];
  EXPECT_EQ(p["id"], "psnr");
  EXPECT_EQ(p["compare"], ">=");
  EXPECT_EQ(p["target"], 40.0);
  EXPECT_EQ(p["met"], false);
  EXPECT_EQ(p["worst"], 34.0);
  ASSERT_EQ(p["figures"].size(), 3u);
  EXPECT_EQ(p["figures"][0]["scene"], "Suzanne");  // worst first, the unmeasured last
  EXPECT_EQ(p["figures"][1]["scene"], "Duck");
  EXPECT_EQ(p["figures"][2]["scene"], "Box");
  EXPECT_TRUE(p["figures"][2]["value"].is_null());
  EXPECT_TRUE(p["figures"][2]["met"].is_null());
  EXPECT_EQ(p["figures"][2]["note"], "skipped: not found");
  for (const char* field : {"scene", "size", "detail", "value", "before", "ratio_to_before", "met", "note", "context"})
    EXPECT_TRUE(p["figures"][0].contains(field)) << field;

  const auto& g = json["rows"][1];
  EXPECT_EQ(g["relative_to_before"], true);
  EXPECT_EQ(g["figures"][0]["before"], 150.0);
  EXPECT_DOUBLE_EQ(g["figures"][0]["ratio_to_before"].get<double>(), 0.4);
  EXPECT_EQ(g["figures"][0]["met"], true);
  EXPECT_EQ(g["met"], true);
  EXPECT_DOUBLE_EQ(g["worst"].get<double>(), 0.4);

  const std::string md = sg::app::targetsMarkdown(json);
  for (const char* text : {"| PSNR | models | 34 | ≥ 40 dB | **not met** (1 met of 2 judged, 3 figures) |",
                           "| forward frame | heavy | 0.4× | ≤ 0.5× before | met (1 met of 1 judged, 1 figures) |",
                           "| PSNR | Box | 64x36 |  | — | dB | — | — | not judged | skipped: not found |"})
    EXPECT_NE(md.find(text), std::string::npos) << text << "\nin:\n" << md;
}

}  // namespace
