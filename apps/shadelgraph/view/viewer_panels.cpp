// The viewer's Dear ImGui panels: per-pass timings with their history, the
// compiled frame graph, decoupled shading's counters, and the controls.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "../frame_setup.hpp"
#include "viewer.hpp"

namespace sg::app::view {
namespace {

std::string mib(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f MiB", double(bytes) / (1 << 20));
  return text;
}

void timingPanel(Viewer& viewer) {
  const auto& t = viewer.lastFrame().timings;
  ImGui::Text("frame %.2f ms wall, %.2f ms GPU", t.frameMs, t.gpuMs);
  if (!ImGui::BeginTable("passes", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) return;
  ImGui::TableSetupColumn("pass");
  ImGui::TableSetupColumn("queue");
  ImGui::TableSetupColumn("GPU ms");
  ImGui::TableSetupColumn("CPU ms");
  ImGui::TableSetupColumn("GPU, last frames");
  ImGui::TableHeadersRow();
  for (const auto& p : t.passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(p.name.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(std::string(graph::toString(p.queue)).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", p.gpuMs);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", p.cpuMs);
    ImGui::TableNextColumn();
    const auto& history = viewer.history().of(p.name);
    ImGui::PushID(p.name.c_str());
    ImGui::PlotLines("", history.data(), int(history.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(110, 16));
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void graphPanel(Viewer& viewer) {
  const auto& plan = viewer.lastFrame().plan;
  if (!plan) return;
  ImGui::Text("%zu passes (%zu kept), %zu batches, heaps %s (%s without aliasing)", plan->passes.size(), plan->order.size(),
              plan->batches.size(), mib(plan->heapBytes).c_str(), mib(plan->heapBytesWithoutAliasing).c_str());
  if (ImGui::TreeNodeEx("passes", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const auto& p : plan->passes) {
      const std::string queue(graph::toString(p.queue));
      if (p.culled)
        ImGui::TextDisabled("%-22s culled", p.name.c_str());
      else
        ImGui::Text("%-22s %-13s batch %u", p.name.c_str(), queue.c_str(), p.batch);
    }
    ImGui::TreePop();
  }
  if (ImGui::TreeNode("resources")) {
    for (uint32_t r = 0; r < plan->resources.size(); ++r) {
      const auto& res = plan->resources[r];
      std::string aliases;
      for (const auto& other : plan->aliasesOf(graph::ResourceId{r}))
        aliases += (aliases.empty() ? " aliases " : ", ") + plan->resources[other.index].name;
      if (res.culled)
        ImGui::TextDisabled("%s: culled", res.name.c_str());
      else if (res.memory.placed())
        ImGui::Text("%s: heap %u +%s, %s%s", res.name.c_str(), res.memory.heap, mib(res.memory.offset).c_str(),
                    mib(res.memory.size).c_str(), aliases.c_str());
      else
        ImGui::Text("%s: external", res.name.c_str());
    }
    ImGui::TreePop();
  }
}

void countersPanel(Viewer& viewer) {
  const auto& d = viewer.stats();
  const auto& c = d.counters;
  ImGui::Text("objects decoupled %u of %zu", d.objects, viewer.session().scene.instances.size());
  ImGui::Text("shadels marked %llu, allocated %llu of %llu", 64ull * c.chunksMarked, 64ull * c.chunksAllocated,
              64ull * d.capacityChunks);
  ImGui::Text("overflow chunks %u, composite misses %u", c.overflowChunks, c.compositeMisses);
  ImGui::Text("shadels per covered pixel %.2f", plugins::shadelsPerCoveredPixel(c));
  ImGui::Text("bias %.2f, reused %llu shadels, shaded %llu", double(d.bias), 64ull * c.chunksReused, 64ull * c.chunksShaded);
  ImGui::Text("shade storage %s, %s", mib(d.storageBytes).c_str(), d.shadeFrame ? "shade frame" : "fill frame");
}

bool combo(const char* label, int& index, const std::vector<std::string>& items) {
  bool changed = false;
  if (ImGui::BeginCombo(label, index >= 0 && size_t(index) < items.size() ? items[size_t(index)].c_str() : "")) {
    for (int i = 0; i < int(items.size()); ++i)
      if (ImGui::Selectable(items[size_t(i)].c_str(), i == index)) {
        index = i;
        changed = true;
      }
    ImGui::EndCombo();
  }
  return changed;
}

void controlsPanel(Viewer& viewer) {
  auto& s = viewer.decoupledSettings();
  int mode = viewer.globalMode();
  if (combo("mode", mode, {"each object's own", "forward", "decoupled", "auto"})) viewer.setGlobalMode(mode);
  int view = viewer.viewIndex();
  if (combo("view", view, Viewer::viewNames())) viewer.setView(view);
  if (combo("filter", s.filter, {"point", "bilinear", "trilinear"})) viewer.rebuildRenderer();
  bool fixedBias = s.fixedBias.has_value();
  float bias = s.fixedBias.value_or(viewer.stats().bias);
  if (ImGui::Checkbox("fixed bias", &fixedBias) || (fixedBias && ImGui::SliderFloat("bias", &bias, -8.0f, 8.0f))) {
    s.fixedBias = fixedBias ? std::optional<float>(bias) : std::nullopt;
    viewer.session().decoupled->setFixedBias(s.fixedBias);
  }
  // Storage takes a new renderer: made when the slider is let go, not at every step of the drag.
  static float storage = -1.0f;
  if (storage < 0.0f) storage = float(s.storageFactor);
  ImGui::SliderFloat("storage", &storage, 1.25f, 8.0f, "%.2f shadels/pixel");
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    s.storageFactor = storage;
    viewer.rebuildRenderer();
  }
  int rate = int(s.shadeRate);
  if (ImGui::SliderInt("shade rate", &rate, 1, 8)) {
    s.shadeRate = uint32_t(rate);
    viewer.rebuildRenderer();
  }
  int camera = viewer.cameraChoice() < 0 ? 0 : viewer.cameraChoice() + 1;
  auto cameras = viewer.cameraNames();
  cameras.insert(cameras.begin(), "free (drag, wheel, W A S D)");
  if (combo("camera", camera, cameras)) viewer.chooseCamera(camera - 1);
  const auto effects = viewer.effects();
  for (size_t e = 0; e < effects.size(); ++e) {
    bool on = viewer.effectOn(effects[e]);
    if (e > 0) ImGui::SameLine();
    if (ImGui::Checkbox(effects[e].c_str(), &on)) viewer.setEffect(effects[e], on);
  }
  ImGui::Checkbox("pause", &viewer.paused);
  if (ImGui::Button("save frame")) viewer.saveFrame(viewer.nextScreenshotPath());
  ImGui::SameLine();
  if (ImGui::Button("save window")) viewer.requestWindowScreenshot(viewer.nextScreenshotPath());

  ImGui::Separator();
  const auto& scene = viewer.session().scene;
  int object = viewer.selected ? int(*viewer.selected) : -1;
  std::vector<std::string> names;
  for (const auto& instance : scene.instances) names.push_back(instance.name);
  if (combo("object", object, names)) viewer.selected = uint32_t(object);
  if (!viewer.selected) {
    ImGui::TextDisabled("click an object to switch it between decoupled and forward");
    return;
  }
  const uint32_t i = *viewer.selected;
  const auto requested = viewer.session().renderer->objectModes()[i];
  int objectMode = requested == scene::ShadingMode::Auto ? 0 : requested == scene::ShadingMode::Decoupled ? 1 : 2;
  bool changed = ImGui::RadioButton("auto", &objectMode, 0);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("decoupled", &objectMode, 1);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("forward", &objectMode, 2);
  if (changed)
    viewer.setObjectMode(i, objectMode == 0 ? scene::ShadingMode::Auto
                            : objectMode == 1 ? scene::ShadingMode::Decoupled
                                              : scene::ShadingMode::Forward);
  const auto materials = viewer.session().registry.materialNames();
  int material = -1;
  for (size_t m = 0; m < materials.size(); ++m)
    if (materials[m] == viewer.objectMaterial(i)) material = int(m);
  if (combo("material", material, materials)) viewer.setObjectMaterial(i, materials[size_t(material)]);
  for (const auto& choice : viewer.session().decoupled->choices())
    if (choice.instance == i) ImGui::TextWrapped("%s", choice.reason.c_str());
}

}  // namespace

void drawPanels(Viewer& viewer) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Once);
  ImGui::SetNextWindowSize(ImVec2(std::min(430.0f, display.x * 0.36f), display.y * 0.9f), ImGuiCond_Once);
  if (ImGui::Begin("frame")) {
    if (ImGui::CollapsingHeader("timings", ImGuiTreeNodeFlags_DefaultOpen)) timingPanel(viewer);
    if (ImGui::CollapsingHeader("frame graph", ImGuiTreeNodeFlags_DefaultOpen)) graphPanel(viewer);
  }
  ImGui::End();
  const float shadingWidth = std::min(360.0f, display.x * 0.3f);
  ImGui::SetNextWindowPos(ImVec2(display.x - shadingWidth - 8, 8), ImGuiCond_Once);
  ImGui::SetNextWindowSize(ImVec2(shadingWidth, display.y * 0.9f), ImGuiCond_Once);
  if (ImGui::Begin("shading")) {
    if (ImGui::CollapsingHeader("counters", ImGuiTreeNodeFlags_DefaultOpen)) countersPanel(viewer);
    if (ImGui::CollapsingHeader("controls", ImGuiTreeNodeFlags_DefaultOpen)) controlsPanel(viewer);
  }
  ImGui::End();
}

}  // namespace sg::app::view
