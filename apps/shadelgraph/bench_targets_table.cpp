// Judging and writing issue 14's target table (bench_targets_table.hpp).
#include "bench_targets_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace sg::app {
namespace {

// The number the target bounds: the value, or value ÷ before for a relative target.
std::optional<double> judged(const TargetRow& row, const TargetFigure& figure) {
  if (!figure.value) return std::nullopt;
  if (!row.relativeToBefore) return figure.value;
  if (!figure.before || *figure.before <= 0.0) return std::nullopt;
  return *figure.value / *figure.before;
}

// Worse for the row's target comes first.
bool worse(const TargetRow& row, double a, double b) { return row.compare == TargetCompare::AtMost ? a > b : a < b; }

nlohmann::json optionalJson(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
nlohmann::json optionalJson(const std::optional<bool>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

std::string key(const std::string& row, const nlohmann::json& f) {
  return row + '\n' + f.value("scene", "") + '\n' + f.value("size", "") + '\n' + f.value("detail", "");
}

// Three significant digits, no exponent.
std::string number(const nlohmann::json& v) {
  if (!v.is_number()) return "—";
  const double x = v.get<double>();
  char text[64];
  if (std::abs(x) >= 1000.0) std::snprintf(text, sizeof text, "%.0f", x);
  else std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

std::string metText(const nlohmann::json& met) {
  if (met.is_null()) return "not judged";
  return met.get<bool>() ? "met" : "**not met**";
}

std::string targetText(const nlohmann::json& row) {
  std::string text = row["compare"].get<std::string>() == "<=" ? "≤ " : "≥ ";
  text += number(row["target"]);
  if (row["relative_to_before"].get<bool>()) text += "× before";
  else if (row["unit"] != "ratio") text += " " + row["unit"].get<std::string>();
  return text;
}

}  // namespace

std::optional<bool> figureMet(const TargetRow& row, const TargetFigure& figure) {
  const auto v = judged(row, figure);
  if (!v) return std::nullopt;
  return row.compare == TargetCompare::AtMost ? *v <= row.target : *v >= row.target;
}

std::optional<bool> rowMet(const TargetRow& row) {
  bool all = !row.figures.empty();
  for (const auto& f : row.figures) {
    const auto met = figureMet(row, f);
    if (met && !*met) return false;
    all = all && met.has_value();
  }
  return all ? std::optional<bool>(true) : std::nullopt;
}

void applyBaseline(std::vector<TargetRow>& rows, const nlohmann::json& baseline) {
  std::map<std::string, double> before;
  if (baseline.contains("rows"))
    for (const auto& row : baseline["rows"])
      for (const auto& f : row.value("figures", nlohmann::json::array()))
        if (f.contains("value") && f["value"].is_number())
          before[key(row.value("id", ""), f)] = f["value"].get<double>();
  for (auto& row : rows)
    for (auto& f : row.figures) {
      const auto found = before.find(key(row.id, {{"scene", f.scene}, {"size", f.size}, {"detail", f.detail}}));
      if (found != before.end()) f.before = found->second;
    }
}

nlohmann::json targetsJson(std::vector<TargetRow> rows, const nlohmann::json& header) {
  nlohmann::json out = header.is_object() ? header : nlohmann::json::object();
  out["rows"] = nlohmann::json::array();
  for (auto& row : rows) {
    if (row.worstFirst)
      std::stable_sort(row.figures.begin(), row.figures.end(), [&](const TargetFigure& a, const TargetFigure& b) {
        const auto va = judged(row, a), vb = judged(row, b);
        if (!va || !vb) return va.has_value() && !vb.has_value();  // unjudged last
        return worse(row, *va, *vb);
      });
    std::optional<double> worst;
    nlohmann::json figures = nlohmann::json::array();
    for (const auto& f : row.figures) {
      const auto v = judged(row, f);
      if (v && (!worst || worse(row, *v, *worst))) worst = v;
      figures.push_back({{"scene", f.scene},
                         {"size", f.size},
                         {"detail", f.detail},
                         {"value", optionalJson(f.value)},
                         {"before", optionalJson(f.before)},
                         {"ratio_to_before", f.value && f.before && *f.before > 0.0 ? nlohmann::json(*f.value / *f.before)
                                                                                     : nlohmann::json(nullptr)},
                         {"met", optionalJson(figureMet(row, f))},
                         {"note", f.note},
                         {"context", f.context}});
    }
    out["rows"].push_back({{"id", row.id},
                           {"figure", row.figure},
                           {"scenes", row.scenes},
                           {"unit", row.unit},
                           {"compare", row.compare == TargetCompare::AtMost ? "<=" : ">="},
                           {"target", row.target},
                           {"relative_to_before", row.relativeToBefore},
                           {"met", optionalJson(rowMet(row))},
                           {"worst", optionalJson(worst)},
                           {"note", row.note},
                           {"figures", figures}});
  }
  return out;
}

std::string targetsMarkdown(const nlohmann::json& targets) {
  std::ostringstream md;
  md << "# Issue 14 targets (`shadelgraph bench targets`)\n\n";
  if (targets.contains("machine")) {
    const auto& m = targets["machine"];
    md << "Machine: " << m.value("cpu", "?") << ", " << m.value("cores", 0) << " cores, " << m.value("device", "?")
       << " (" << m.value("driver", "?") << ").";
  }
  if (targets.contains("repetitions")) md << " Timed rounds: " << targets["repetitions"] << ", medians.";
  if (targets.contains("baseline") && targets["baseline"].is_string())
    md << " Before: `" << targets["baseline"].get<std::string>() << "`.";
  md << "\n\n| figure | scenes | worst | target | met |\n|---|---|---|---|---|\n";
  for (const auto& row : targets["rows"]) {
    std::size_t judgedCount = 0, metCount = 0;
    for (const auto& f : row["figures"])
      if (!f["met"].is_null()) {
        ++judgedCount;
        metCount += f["met"].get<bool>() ? 1 : 0;
      }
    md << "| " << row["figure"].get<std::string>() << " | " << row["scenes"].get<std::string>() << " | "
       << number(row["worst"]) << (row["relative_to_before"].get<bool>() && row["worst"].is_number() ? "×" : "")
       << " | " << targetText(row) << " | " << metText(row["met"]) << " (" << metCount << " met of " << judgedCount
       << " judged, " << row["figures"].size() << " figures) |\n";
  }
  md << "\n## Every figure\n\n| figure | scene | size | detail | value | unit | before | ÷ before | met | note |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : targets["rows"]) {
    if (row["figures"].empty())
      md << "| " << row["figure"].get<std::string>() << " | | | | — | | | | not judged | " << row["note"].get<std::string>()
         << " |\n";
    for (const auto& f : row["figures"])
      md << "| " << row["figure"].get<std::string>() << " | " << f["scene"].get<std::string>() << " | "
         << f["size"].get<std::string>() << " | " << f["detail"].get<std::string>() << " | " << number(f["value"])
         << " | " << row["unit"].get<std::string>() << " | " << number(f["before"]) << " | "
         << number(f["ratio_to_before"]) << " | " << metText(f["met"]) << " | " << f["note"].get<std::string>()
         << " |\n";
  }
  std::string notes;
  for (const auto& row : targets["rows"])
    if (!row["note"].get<std::string>().empty())
      notes += "- " + row["figure"].get<std::string>() + ": " + row["note"].get<std::string>() + "\n";
  if (!notes.empty()) md << "\n## Notes\n\n" << notes;
  return md.str();
}

}  // namespace sg::app
