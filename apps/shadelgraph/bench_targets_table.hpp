#pragma once
// The table of issue 14's targets that `shadelgraph bench targets` writes:
// figures in, each judged against its row's target (met, not met, or not
// measured), out as targets.json and targets.md. No device: the measuring is
// in bench_targets.cpp.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sg::app {

enum class TargetCompare { AtMost, AtLeast };

// One measured figure of a row: for one scene, size and variant (e.g. the path).
struct TargetFigure {
  std::string scene;
  std::string size;    // "1280x720"; empty where no size applies (graph compile)
  std::string detail;  // what else tells figures of a row apart ("forward", "100 passes", ...)
  std::optional<double> value;   // empty: not measured (`note` says why)
  std::optional<double> before;  // the same figure in the baseline (--baseline-json)
  std::string note;
  nlohmann::json context = nlohmann::json::object();  // what the figure came from (ms, bytes, ...)
};

struct TargetRow {
  std::string id;      // stable key, matched against the baseline
  std::string figure;  // what is measured, as the issue words it
  std::string scenes;  // where, as the issue words it
  std::string unit;    // of value: "ratio", "ns", "us", "ms", "dB", "shadels/px"
  TargetCompare compare = TargetCompare::AtMost;
  double target = 0.0;
  // The target bounds value ÷ before (e.g. "≤ 0.5× today"): a figure without a before is not judged.
  bool relativeToBefore = false;
  bool worstFirst = false;  // list figures from the worst
  std::string note;
  std::vector<TargetFigure> figures;
};

// Whether a figure meets its row's target; empty when it cannot be judged.
std::optional<bool> figureMet(const TargetRow& row, const TargetFigure& figure);
// Every figure met: true; any not met: false; else (nothing judged, or some not): empty.
std::optional<bool> rowMet(const TargetRow& row);

// Fills each figure's `before` from an earlier targets.json (same row id, scene, size, detail).
void applyBaseline(std::vector<TargetRow>& rows, const nlohmann::json& baseline);

// {"rows": [{id, figure, scenes, unit, compare: "<=" | ">=", target, relative_to_before,
//   met, worst, figures: [{scene, size, detail, value, before, ratio_to_before, met, note, context}]}]}
// with `header` (machine, options, ...) merged in at the top level. Values not measured are null.
nlohmann::json targetsJson(std::vector<TargetRow> rows, const nlohmann::json& header);
// The same as Markdown: a summary table (one line per row) and every figure.
std::string targetsMarkdown(const nlohmann::json& targets);

}  // namespace sg::app
